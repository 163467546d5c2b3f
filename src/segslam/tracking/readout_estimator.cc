#include "segslam/tracking/readout_estimator.h"

#include <Eigen/Cholesky>
#include <algorithm>

#include "segslam/map/map_point.h"

namespace segslam::tracking {

ReadoutEstimator::ReadoutEstimator(double configured_s, double max_abs_s,
                                   ReadoutEstimatorOptions options)
    : options_(options),
      configured_s_(configured_s),
      max_abs_s_(max_abs_s),
      readout_(std::clamp(configured_s, -max_abs_s, max_abs_s)) {}

ReadoutEvidence readoutEvidence(const map::Frame& frame, double readout_s) {
  // Residuals beyond the 95 % quantile of chi-square with 2 degrees of freedom are outliers.
  constexpr double kMaxChi2 = 5.991;
  ReadoutEvidence evidence{readout_s, 0.0, 0.0};
  if (frame.readout_gradient.size() != frame.size()) return evidence;
  const core::Camera& camera = frame.camera->camera;
  // The pose was optimised with the readout fixed and takes up part of what a wrong readout does
  // to the residuals (a roll shears the rows too): the readout's step and information are those
  // left once the pose is eliminated (Schur complement of the 7-parameter normal equations).
  Eigen::Matrix<double, 6, 6> pose_information = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> pose_gradient = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> pose_residual = Eigen::Matrix<double, 6, 1>::Zero();
  double gradient_residual = 0.0;
  double gradient_information = 0.0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const auto& point = frame.map_points[i];
    if (!point || point->bad || point->provisional || frame.outlier[i]) continue;
    const Eigen::Vector3d in_camera = frame.T_cw * point->position;
    if (in_camera.z() <= 0.0) continue;
    const cv::Point2f& keypoint = frame.keypoints_un[i].pt;
    const Eigen::Vector2d residual =
        camera.project(in_camera) - Eigen::Vector2d(keypoint.x, keypoint.y);
    const double weight = frame.camera->levels.inverseSigma2()[frame.keypoints_un[i].octave];
    if (weight * residual.squaredNorm() > kMaxChi2) continue;
    // The projection's derivative with respect to a small rotation and translation of the
    // camera frame (left perturbation: X -> X + w x X + t).
    const double inverse_z = 1.0 / in_camera.z();
    Eigen::Matrix<double, 2, 3> projection;
    projection << camera.fx * inverse_z, 0.0, -camera.fx * in_camera.x() * inverse_z * inverse_z,
        0.0, camera.fy * inverse_z, -camera.fy * in_camera.y() * inverse_z * inverse_z;
    Eigen::Matrix3d rotation;
    rotation << 0.0, in_camera.z(), -in_camera.y(), -in_camera.z(), 0.0, in_camera.x(),
        in_camera.y(), -in_camera.x(), 0.0;
    Eigen::Matrix<double, 2, 6> jacobian;
    jacobian << projection * rotation, projection;
    // The keypoint moves by the gradient per second of readout: the residual by minus that.
    const Eigen::Vector2d gradient = -frame.readout_gradient[i];
    pose_information += weight * jacobian.transpose() * jacobian;
    pose_gradient += weight * jacobian.transpose() * gradient;
    pose_residual += weight * jacobian.transpose() * residual;
    gradient_residual += weight * gradient.dot(residual);
    gradient_information += weight * gradient.squaredNorm();
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> pose(pose_information);
  if (pose.info() != Eigen::Success || !pose.isPositive()) return evidence;
  const Eigen::Matrix<double, 6, 1> through_pose = pose.solve(pose_gradient);
  const double information = gradient_information - pose_gradient.dot(through_pose);
  if (!(information > 0.0)) return evidence;
  // Gauss-Newton: the step that lowers the residuals is minus (J^T r) / (J^T J).
  evidence.residual_along_gradient = -(gradient_residual - through_pose.dot(pose_residual));
  evidence.information = information;
  return evidence;
}

void ReadoutEstimator::addFrame(const ReadoutEvidence& evidence) {
  if (configured_s_ == 0.0) return;
  information_ *= options_.forgetting;
  weighted_sum_ *= options_.forgetting;
  if (evidence.information > 0.0) {
    const double step = evidence.residual_along_gradient / evidence.information;
    information_ += evidence.information;
    weighted_sum_ += evidence.information * (evidence.readout_s + step);
  }
  readout_ = std::clamp((options_.prior_information * configured_s_ + weighted_sum_) /
                            (options_.prior_information + information_),
                        -max_abs_s_, max_abs_s_);
}

}  // namespace segslam::tracking
