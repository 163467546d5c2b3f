#include "segslam/synth/push_motion.h"

namespace segslam::synth {

geometry::Pose PushMotion::at(double t) const {
  if (t <= begin_time || end_time <= begin_time) return start;
  if (t >= end_time) return end;
  const double x = (t - begin_time) / (end_time - begin_time);
  const double eased = x * x * (3.0 - 2.0 * x);
  const Eigen::Quaterniond q_start(start.linear());
  const Eigen::Quaterniond q_end(end.linear());
  geometry::Pose pose = geometry::Pose::Identity();
  pose.linear() = q_start.slerp(eased, q_end).toRotationMatrix();
  pose.translation() = start.translation() + eased * (end.translation() - start.translation());
  return pose;
}

}  // namespace segslam::synth
