#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "segslam/map/frame.h"
#include "segslam/map/keyframe.h"

namespace segslam::tracking {

// Whether a candidate's pose is taken; called with the frame's map_points holding the PnP
// inliers and frame.reference_keyframe the candidate. It may refine the frame's matches.
using RelocalisationCheck = std::function<bool(const geometry::Pose& T_cw)>;

// Finds the pose of a frame that lost track: descriptor matching against the candidate keyframes
// in the order given, then PnP with RANSAC on the matched map points, until a pose passes
// `accept`. A pose the caller refuses (e.g. on points no own mask has checked: the newest
// keyframe's, made while a person walked in) does not end the search, since an older candidate
// may place the frame on checked points. Returns the accepted candidate's PnP pose (the frame's
// map_points and reference_keyframe as `accept` left them), or none with the frame's map_points
// cleared.
std::optional<geometry::Pose> relocaliseAgainstKeyFrames(
    map::Frame& frame, const std::vector<std::shared_ptr<map::KeyFrame>>& candidates,
    const RelocalisationCheck& accept);

}  // namespace segslam::tracking
