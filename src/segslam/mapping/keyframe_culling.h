#pragma once

#include "segslam/map/keyframe.h"

namespace segslam::mapping {

struct KeyFrameCullingOptions {
  // Redundant: more than this share of the keyframe's close points is seen by at least three
  // other keyframes at the same or a finer scale.
  double redundant_share = 0.9;
  // Crowded: a live covisible keyframe with at least as many map points sees at least this share
  // of the keyframe's points from nearly the same pose (camera centres closer than
  // crowded_distance_m, optical axes within crowded_angle_deg). 0 = never crowded.
  double crowded_covisible_share = 0.5;
  double crowded_distance_m = 0.03;
  double crowded_angle_deg = 10.0;
  // Orphaned: fewer valid map points than this.
  int orphaned_below_points = 20;
};

// Whether local mapping may remove the keyframe (its covisible keyframes cover what it adds).
// With people walking through, the points a keyframe alone observes (made in a gap between them,
// or left with few observations by their masks) keep it under the redundant share for ever;
// every revisit of mapped space would then add keyframes without end, so a keyframe with a
// stronger twin at the same pose goes too. Both are read under the map mutex.
[[nodiscard]] bool isRedundant(const map::KeyFrame& keyframe,
                               const KeyFrameCullingOptions& options);
[[nodiscard]] bool isCrowded(const map::KeyFrame& keyframe, const KeyFrameCullingOptions& options);
// A keyframe whose points were culled (seen through, on a late mask, failed local BA) anchors
// neither tracking nor bundle adjustment, and no covisibility edge leads to it any more, so the
// two rules above never judge it: in long runs with people such keyframes, many made while
// tracking strayed, were 20 of 47 live ones, each holding its features and dense cloud.
[[nodiscard]] bool isOrphaned(const map::KeyFrame& keyframe, const KeyFrameCullingOptions& options);

}  // namespace segslam::mapping
