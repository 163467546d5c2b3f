#pragma once

#include <optional>
#include <vector>

#include "segslam/geometry/pose.h"

namespace segslam::core {

struct StampedPose {
  double timestamp = 0.0;                            // seconds
  geometry::Pose T_wc = geometry::Pose::Identity();  // camera-to-world
};

// A camera trajectory: poses ordered by strictly increasing timestamp.
class Trajectory {
 public:
  Trajectory() = default;
  explicit Trajectory(std::vector<StampedPose> poses);

  // Appends a pose; its timestamp must be larger than the last one's.
  void append(double timestamp, const geometry::Pose& T_wc);

  [[nodiscard]] const std::vector<StampedPose>& poses() const { return poses_; }
  [[nodiscard]] std::size_t size() const { return poses_.size(); }
  [[nodiscard]] bool empty() const { return poses_.empty(); }
  [[nodiscard]] const StampedPose& operator[](std::size_t i) const { return poses_[i]; }
  [[nodiscard]] std::vector<double> timestamps() const;

  // Pose at an exact timestamp (within `tolerance` seconds), if present.
  [[nodiscard]] std::optional<geometry::Pose> poseAt(double timestamp,
                                                     double tolerance = 1e-6) const;

 private:
  std::vector<StampedPose> poses_;
};

}  // namespace segslam::core
