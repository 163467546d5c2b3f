#pragma once

#include "segslam/geometry/pose.h"

namespace segslam::tracking {

// A camera carried by hand or by a robot moves a few metres per second at most. A tracked pose
// that jumps farther from the last frame's is a wrong solution: matches on a person the masks
// missed, a repeated texture. Taken as tracked, it would become a keyframe whose own points
// carry the next frames along with it, a fragment of map far from the rest that no loop joins.
struct MotionLimitOptions {
  double max_speed_m_per_s = 3.0;  // 0 = no limit
  // Pose noise allowed on top, so that frames with nearly equal timestamps are not refused.
  double margin_m = 0.03;
};

// Whether a camera may have moved from T_cw_last (at t_last seconds) to T_cw (at t) (world to
// camera poses); a timestamp going back counts as no time.
[[nodiscard]] bool withinMotionLimit(const geometry::Pose& T_cw_last, double t_last,
                                     const geometry::Pose& T_cw, double t,
                                     const MotionLimitOptions& options);

}  // namespace segslam::tracking
