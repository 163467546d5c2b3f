#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <utility>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/dense/keyframe_cloud.h"

namespace segslam::dense {

// What a keyframe's depth says is empty space: its image cut into square cells, each holding the
// nearest depth the keyframe measured in it (its own static and dynamic points; a person in
// front of a surface hides it, it does not clear it).
class FreeSpaceView {
 public:
  // cell_px: cell edge in pixels; a cell with fewer than min_points points tells nothing.
  FreeSpaceView(const core::Camera& camera, const KeyFrameCloud& cloud, int cell_px = 16,
                int min_points = 3);

  // Whether the keyframe saw past `point_c` (its camera frame): it projects into a cell where
  // every depth measured lies more than 5 cm + 2 % of its depth behind it.
  [[nodiscard]] bool seesThrough(const Eigen::Vector3f& point_c) const;

 private:
  core::Camera camera_;
  int cell_px_;
  int min_points_;
  int cols_;
  int rows_;
  std::vector<float> nearest_;  // by cell, row-major
  std::vector<int> points_;
};

// The points of an earlier map (world frame) that none of `views` (camera-to-world pose and the
// keyframe's cloud in its camera frame) sees through: what moved away since the earlier map was
// made goes, what the views did not look at stays.
LabelledCloud withoutSeenThrough(
    const LabelledCloud& earlier, const core::Camera& camera,
    const std::vector<std::pair<Eigen::Isometry3d, const KeyFrameCloud*>>& views);

}  // namespace segslam::dense
