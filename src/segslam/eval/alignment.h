#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "segslam/geometry/pose.h"

namespace segslam::eval {

// How an estimated trajectory is brought into the ground-truth frame before ATE.
enum class AlignmentMethod {
  kSe3,   // rotation and translation (Horn), as TUM evaluate_ate.py
  kSim3,  // rotation, translation and scale (Umeyama), for monocular-like estimates
  kNone,  // compare raw positions
};

// "se3", "sim3", "none".
std::string_view alignmentMethodName(AlignmentMethod method);
std::vector<std::string> alignmentMethodNames();
std::optional<AlignmentMethod> parseAlignmentMethod(std::string_view name);

// The similarity x -> scale * rotation * x + translation.
struct Alignment {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;

  [[nodiscard]] Eigen::Vector3d apply(const Eigen::Vector3d& point) const;
  // Maps the position and rotates the orientation (scale affects the position only).
  [[nodiscard]] geometry::Pose apply(const geometry::Pose& pose) const;
  // Homogeneous 4x4 matrix [scale * rotation, translation; 0 0 0 1].
  [[nodiscard]] Eigen::Matrix4d matrix() const;
  // The similarity that undoes this one (scale must not be zero).
  [[nodiscard]] Alignment inverse() const;
};

// The alignment that maps the `source` points (3xN) onto the `target` points (3xN, same order)
// with least squared error. SE(3) reproduces TUM evaluate_ate.py: W = sum source_c target_c^T,
// U D V^T = svd(W^T), R = U S V^T with S = diag(1, 1, -1) when det(U) det(V) < 0, and
// t = mean(target) - R mean(source). Sim(3) adds Umeyama's scale trace(D S) / sum |source_c|^2.
Alignment alignPoints(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                      AlignmentMethod method);

}  // namespace segslam::eval
