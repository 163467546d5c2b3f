#include "segslam/geometry/pose.h"

#include <algorithm>
#include <cmath>

namespace segslam::geometry {

Pose poseFromTranslationQuaternion(const Eigen::Vector3d& t, const Eigen::Quaterniond& q) {
  Pose pose = Pose::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = t;
  return pose;
}

Pose orthonormalised(const Pose& pose) {
  Pose result = pose;
  result.linear() = Eigen::Quaterniond(pose.linear()).normalized().toRotationMatrix();
  return result;
}

double rotationAngle(const Pose& pose) {
  const double c = (pose.linear().trace() - 1.0) / 2.0;
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double rotationAngleAccurate(const Pose& pose) {
  return Eigen::AngleAxisd(Eigen::Quaterniond(pose.linear())).angle();
}

}  // namespace segslam::geometry
