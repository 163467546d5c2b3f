#include "segslam/synth/primitives.h"

#include <cmath>
#include <numbers>

namespace segslam::synth {

std::array<Eigen::Vector3d, 4> Rect::corners() const {
  const Eigen::Vector3d u = axis_u * size_u;
  const Eigen::Vector3d v = axis_v * size_v;
  return {origin, origin + u, origin + u + v, origin + v};
}

Eigen::Vector2d Ellipsoid::textureExtent() const {
  return {std::numbers::pi * (radii[0] + radii[1]), 2.0 * radii[2]};
}

std::array<Eigen::Vector3d, 8> Ellipsoid::boxCorners() const {
  std::array<Eigen::Vector3d, 8> corners;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d signs((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    corners[i] = center + axes * signs.cwiseProduct(radii);
  }
  return corners;
}

Rect transformed(const geometry::Pose& pose, const Rect& rect) {
  Rect out = rect;
  out.origin = pose * rect.origin;
  out.axis_u = pose.linear() * rect.axis_u;
  out.axis_v = pose.linear() * rect.axis_v;
  return out;
}

Ellipsoid transformed(const geometry::Pose& pose, const Ellipsoid& ellipsoid) {
  Ellipsoid out = ellipsoid;
  out.center = pose * ellipsoid.center;
  out.axes = pose.linear() * ellipsoid.axes;
  return out;
}

Rect flipped(const Rect& rect) {
  Rect out = rect;
  out.origin = rect.origin + rect.axis_u * rect.size_u;
  out.axis_u = -rect.axis_u;
  return out;
}

std::array<Rect, 6> boxFaces(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  const Eigen::Vector3d size = high - low;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  return {
      Rect{{high.x(), low.y(), low.z()}, y, z, size.y(), size.z()},
      Rect{{low.x(), high.y(), low.z()}, -y, z, size.y(), size.z()},
      Rect{{high.x(), high.y(), low.z()}, -x, z, size.x(), size.z()},
      Rect{{low.x(), low.y(), low.z()}, x, z, size.x(), size.z()},
      Rect{{low.x(), low.y(), high.z()}, x, y, size.x(), size.y()},
      Rect{{low.x(), high.y(), low.z()}, x, -y, size.x(), size.y()},
  };
}

Ellipsoid limbBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                      double overlap) {
  const Eigen::Vector3d along = b - a;
  const double length = along.norm();
  const Eigen::Vector3d axis2 =
      length > 1e-12 ? Eigen::Vector3d(along / length) : Eigen::Vector3d(Eigen::Vector3d::UnitZ());
  // Any orthonormal completion works; keep axis 0 close to horizontal so textures look upright.
  Eigen::Vector3d axis0 = Eigen::Vector3d::UnitZ().cross(axis2);
  if (axis0.norm() < 1e-6) axis0 = Eigen::Vector3d::UnitX().cross(axis2);
  axis0.normalize();
  Ellipsoid limb;
  limb.center = 0.5 * (a + b);
  limb.axes.col(0) = axis0;
  limb.axes.col(1) = axis2.cross(axis0);
  limb.axes.col(2) = axis2;
  limb.radii = {radius, radius, 0.5 * length + overlap};
  return limb;
}

}  // namespace segslam::synth
