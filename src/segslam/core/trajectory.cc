#include "segslam/core/trajectory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace segslam::core {

Trajectory::Trajectory(std::vector<StampedPose> poses) : poses_(std::move(poses)) {
  for (std::size_t i = 1; i < poses_.size(); ++i) {
    if (!(poses_[i].timestamp > poses_[i - 1].timestamp)) {
      throw std::invalid_argument("Trajectory: timestamps must be strictly increasing");
    }
  }
}

void Trajectory::append(double timestamp, const geometry::Pose& T_wc) {
  if (!poses_.empty() && !(timestamp > poses_.back().timestamp)) {
    throw std::invalid_argument("Trajectory::append: timestamps must be strictly increasing");
  }
  poses_.push_back({timestamp, T_wc});
}

std::vector<double> Trajectory::timestamps() const {
  std::vector<double> stamps;
  stamps.reserve(poses_.size());
  for (const auto& p : poses_) stamps.push_back(p.timestamp);
  return stamps;
}

std::optional<geometry::Pose> Trajectory::poseAt(double timestamp, double tolerance) const {
  auto it = std::lower_bound(poses_.begin(), poses_.end(), timestamp - tolerance,
                             [](const StampedPose& p, double t) { return p.timestamp < t; });
  if (it != poses_.end() && std::abs(it->timestamp - timestamp) <= tolerance) return it->T_wc;
  return std::nullopt;
}

}  // namespace segslam::core
