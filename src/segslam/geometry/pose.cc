#include "segslam/geometry/pose.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace segslam::geometry {

Pose poseFromTranslationQuaternion(const Eigen::Vector3d& t, const Eigen::Quaterniond& q) {
  Pose pose = Pose::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = t;
  return pose;
}

Pose orthonormalised(const Pose& pose) {
  // The nearest rotation in the Frobenius norm: U V^T of the block's SVD.
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(pose.linear(),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d rotation = svd.matrixU() * svd.matrixV().transpose();
  if (rotation.determinant() < 0.0) {
    Eigen::Matrix3d u = svd.matrixU();
    u.col(2) = -u.col(2);
    rotation = u * svd.matrixV().transpose();
  }
  Pose result = pose;
  result.linear() = rotation;
  return result;
}

double rotationAngle(const Pose& pose) {
  const double c = (pose.linear().trace() - 1.0) / 2.0;
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double rotationAngleAccurate(const Pose& pose) {
  return Eigen::AngleAxisd(Eigen::Quaterniond(pose.linear())).angle();
}

}  // namespace segslam::geometry
