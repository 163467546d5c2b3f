#include "segslam/tracking/motion_limit.h"

#include <algorithm>

namespace segslam::tracking {

bool withinMotionLimit(const geometry::Pose& T_cw_last, double t_last, const geometry::Pose& T_cw,
                       double t, const MotionLimitOptions& options) {
  if (options.max_speed_m_per_s <= 0.0) return true;
  const double seconds = std::max(t - t_last, 0.0);
  const double moved = (T_cw.inverse().translation() - T_cw_last.inverse().translation()).norm();
  return moved <= options.max_speed_m_per_s * seconds + options.margin_m;
}

}  // namespace segslam::tracking
