#pragma once

#include "segslam/geometry/pose.h"

namespace segslam::synth {

// A rigid object pushed from one placement to another during a time window: it rests at `start`
// until `begin_time`, then glides (easing in and out) to `end`, reached at `end_time`, and rests
// there. Placements map object coordinates to world coordinates.
struct PushMotion {
  geometry::Pose start = geometry::Pose::Identity();
  geometry::Pose end = geometry::Pose::Identity();
  double begin_time = 0.0;
  double end_time = 0.0;

  [[nodiscard]] geometry::Pose at(double t) const;
};

}  // namespace segslam::synth
