#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "segslam/map/map.h"
#include "segslam/optim/bundle_adjuster.h"

namespace segslam::mapping {

// The keyframes and points of one local bundle adjustment, with the indices the solver uses.
struct LocalWindow {
  std::vector<map::KeyFrame*> keyframes;  // the new keyframe, its covisible ones, then fixed ones
  std::vector<std::shared_ptr<map::MapPoint>> points;
  optim::BundleAdjustmentProblem problem;  // keyframes and observations in the same order
  std::vector<std::pair<map::KeyFrame*, map::MapPoint*>> observation_owners;
};

// Observations by fixed keyframes that hold a window in place. Fewer leave it nearly free: the
// window and its points move as a whole to fit those few (a mismatch among them, a depth off by a
// centimetre), and every tracked pose relative to its keyframes moves with it. A camera that
// starts beside a person and walks away from its first view showed it: the first keyframe, the
// only fixed one, kept 10-60 observations, each local BA moved the window 1-2 cm, and the map
// ended 7 cm from the first keyframe (a step of 7 cm in the trajectory). Mapped sequences keep
// 150-400 of them (TUM, Bonn, composites).
inline constexpr std::size_t kMinAnchorObservations = 100;

// The local window around `keyframe`: it and at most `max_keyframes - 1` of its covisible
// keyframes are optimised, with the points they see; the other keyframes that see those points
// are fixed. When those see fewer than kMinAnchorObservations, the oldest optimised keyframe but
// `keyframe` is fixed too. Call with the map's mutex held (it tags the keyframes).
LocalWindow collectLocalWindow(map::KeyFrame& keyframe, std::size_t max_keyframes);

}  // namespace segslam::mapping
