#pragma once

#include <Eigen/Core>

#include "segslam/optim/rgbd_observation.h"

// Reprojection of a camera-frame point into an RGB-D observation, shared by the pose optimiser
// and the bundle adjuster. Inline because both call it in their innermost loops.
namespace segslam::optim {

// Points nearer than this (or behind the camera) cannot be projected; they count as outliers.
inline constexpr double kMinDepth = 1e-6;

[[nodiscard]] inline bool isInFront(const Eigen::Vector3d& p_c) { return p_c.z() > kMinDepth; }

// Predicted measurement (u, v, u_r) of a camera-frame point in front of the camera.
[[nodiscard]] inline Eigen::Vector3d predictMeasurement(const StereoIntrinsics& k,
                                                        const Eigen::Vector3d& p_c) {
  const double inv_z = 1.0 / p_c.z();
  const double u = k.fx * p_c.x() * inv_z + k.cx;
  return {u, k.fy * p_c.y() * inv_z + k.cy, u - k.bf * inv_z};
}

// Jacobian of predictMeasurement with respect to the camera-frame point.
[[nodiscard]] inline Eigen::Matrix3d predictMeasurementJacobian(const StereoIntrinsics& k,
                                                                const Eigen::Vector3d& p_c) {
  const double inv_z = 1.0 / p_c.z();
  const double inv_z2 = inv_z * inv_z;
  Eigen::Matrix3d jacobian;
  jacobian.row(0) << k.fx * inv_z, 0.0, -k.fx * p_c.x() * inv_z2;
  jacobian.row(1) << 0.0, k.fy * inv_z, -k.fy * p_c.y() * inv_z2;
  jacobian.row(2) << jacobian(0, 0), 0.0, jacobian(0, 2) + k.bf * inv_z2;
  return jacobian;
}

// Jacobian of predictMeasurement(T * p) with respect to a left perturbation T <- exp(xi) T of
// the pose, xi = (rho, phi), under which p_c moves by rho + phi x p_c. Written out entry by entry
// because the pose optimiser evaluates it for every observation at every iteration.
[[nodiscard]] inline Eigen::Matrix<double, 3, 6> predictMeasurementPoseJacobian(
    const StereoIntrinsics& k, const Eigen::Vector3d& p_c) {
  const double inv_z = 1.0 / p_c.z();
  const double x = p_c.x() * inv_z;  // normalised image coordinates
  const double y = p_c.y() * inv_z;
  Eigen::Matrix<double, 3, 6> jacobian;
  jacobian.row(0) << k.fx * inv_z, 0.0, -k.fx * x * inv_z, -k.fx * x * y, k.fx * (1.0 + x * x),
      -k.fx * y;
  jacobian.row(1) << 0.0, k.fy * inv_z, -k.fy * y * inv_z, -k.fy * (1.0 + y * y), k.fy * x * y,
      k.fy * x;
  // u_r = u - bf / z adds d(-bf / z) / dz = bf / z^2 times dz / dxi = (0, 0, 1, y_c, -x_c, 0).
  const double d_disparity = k.bf * inv_z * inv_z;
  jacobian.row(2) = jacobian.row(0);
  jacobian(2, 2) += d_disparity;
  jacobian(2, 3) += d_disparity * p_c.y();
  jacobian(2, 4) -= d_disparity * p_c.x();
  return jacobian;
}

// Observed minus predicted (u, v, u_r). Without depth the third component is zero, so that a
// 2-dof observation can share the 3-row arithmetic of a 3-dof one.
[[nodiscard]] inline Eigen::Vector3d reprojectionResidual(const StereoIntrinsics& k,
                                                          const RgbdObservation& observation,
                                                          const Eigen::Vector3d& p_c) {
  const Eigen::Vector3d predicted = predictMeasurement(k, p_c);
  return {observation.pixel.x() - predicted.x(), observation.pixel.y() - predicted.y(),
          observation.hasDepth() ? observation.right_u - predicted.z() : 0.0};
}

// Information-weighted squared residual, to compare with chi2Threshold(observation).
[[nodiscard]] inline double reprojectionChi2(const StereoIntrinsics& k,
                                             const RgbdObservation& observation,
                                             const Eigen::Vector3d& p_c) {
  return observation.information * reprojectionResidual(k, observation, p_c).squaredNorm();
}

// An observation fits its point when the point is in front and the chi2 test passes.
[[nodiscard]] inline bool isInlierObservation(const StereoIntrinsics& k,
                                              const RgbdObservation& observation,
                                              const Eigen::Vector3d& p_c) {
  return isInFront(p_c) && reprojectionChi2(k, observation, p_c) <= chi2Threshold(observation);
}

}  // namespace segslam::optim
