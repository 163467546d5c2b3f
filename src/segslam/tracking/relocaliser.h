#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "segslam/map/frame.h"
#include "segslam/map/keyframe.h"

namespace segslam::tracking {

// Finds the pose of a frame that lost track: descriptor matching against the candidate keyframes
// in the order given, then PnP with RANSAC on the matched map points, until one succeeds. On
// success the frame's map_points hold the RANSAC inliers and the pose is returned (not yet
// refined).
std::optional<geometry::Pose> relocaliseAgainstKeyFrames(
    map::Frame& frame, const std::vector<std::shared_ptr<map::KeyFrame>>& candidates);

}  // namespace segslam::tracking
