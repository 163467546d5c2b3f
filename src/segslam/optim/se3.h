#pragma once

#include <Eigen/Core>

#include "segslam/geometry/pose.h"

// Exponential and logarithm maps of SE(3), the local coordinates in which the optimisers
// update poses.
namespace segslam::optim {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// The cross-product matrix: skew(a) * b == a.cross(b).
[[nodiscard]] Eigen::Matrix3d skew(const Eigen::Vector3d& v);

// Twists are ordered (rho, phi): translational part first, rotational part second; the rotation
// is by |phi| radians about phi. For small twists exp(xi) * p ~= p + rho + phi x p, which is the
// perturbation the Jacobians assume.
[[nodiscard]] geometry::Pose expSe3(const Vector6d& twist);
// Inverse of expSe3 for rotations of up to pi radians.
[[nodiscard]] Vector6d logSe3(const geometry::Pose& pose);

}  // namespace segslam::optim
