#include "segslam/core/camera.h"

#include <algorithm>

namespace segslam::core {

bool Camera::hasDistortion() const {
  return std::any_of(distortion.begin(), distortion.end(), [](double d) { return d != 0.0; });
}

Eigen::Vector3d Camera::backProject(double u, double v, double z) const {
  return {(u - cx) * z / fx, (v - cy) * z / fy, z};
}

Eigen::Vector2d Camera::project(const Eigen::Vector3d& p_c) const {
  return {fx * p_c.x() / p_c.z() + cx, fy * p_c.y() / p_c.z() + cy};
}

}  // namespace segslam::core
