#pragma once

// Small hand-made trajectories for the eval tests only (header-only, never in the library).

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

#include "segslam/core/trajectory.h"

namespace segslam::eval::fixtures {

// A pose at `position`, rotated by `yaw_deg` about z.
inline geometry::Pose poseAt(const Eigen::Vector3d& position, double yaw_deg = 0.0) {
  geometry::Pose pose = geometry::Pose::Identity();
  pose.linear() =
      Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).matrix();
  pose.translation() = position;
  return pose;
}

// Unrotated poses at the given x positions (y = z = 0).
inline core::Trajectory alongX(const std::vector<double>& stamps, const std::vector<double>& xs) {
  core::Trajectory trajectory;
  for (std::size_t k = 0; k < stamps.size(); ++k) {
    trajectory.append(stamps[k], poseAt({xs[k], 0.0, 0.0}));
  }
  return trajectory;
}

// A curvy 3D path that rotates as it goes, sampled at 10 Hz.
inline core::Trajectory wigglyPath(std::size_t count) {
  core::Trajectory trajectory;
  for (std::size_t k = 0; k < count; ++k) {
    const double t = 0.1 * static_cast<double>(k);
    trajectory.append(100.0 + t, poseAt({std::sin(t), 0.5 * std::cos(0.7 * t), 0.2 * t}, 20.0 * t));
  }
  return trajectory;
}

// Applies `transform` on the world side of every pose: the same path seen in another frame.
inline core::Trajectory transformed(const core::Trajectory& trajectory,
                                    const geometry::Pose& transform) {
  core::Trajectory result;
  for (const auto& pose : trajectory.poses()) result.append(pose.timestamp, transform * pose.T_wc);
  return result;
}

inline std::vector<double> stampsFrom(double first, double step, std::size_t count) {
  std::vector<double> stamps;
  for (std::size_t k = 0; k < count; ++k) stamps.push_back(first + step * static_cast<double>(k));
  return stamps;
}

}  // namespace segslam::eval::fixtures
