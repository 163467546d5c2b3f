#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "segslam/map/frame.h"
#include "segslam/map/keyframe.h"

namespace segslam::tracking {

// Finds the pose of a frame that lost track: descriptor matching against candidate keyframes
// (the most recent ones first), then PnP with RANSAC on the matched map points. On success the
// frame's map_points hold the RANSAC inliers and the pose is returned (not yet refined).
// Bag-of-words candidate retrieval replaces the recency order once place recognition exists.
std::optional<geometry::Pose> relocaliseAgainstKeyFrames(
    map::Frame& frame, const std::vector<std::shared_ptr<map::KeyFrame>>& keyframes,
    std::size_t max_candidates = 15);

}  // namespace segslam::tracking
