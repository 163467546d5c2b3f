#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "segslam/core/semantic_class.h"
#include "segslam/geometry/pose.h"
#include "segslam/synth/texture.h"

namespace segslam::synth {

// What a rendered pixel of a primitive reports besides its colour.
struct SurfaceInfo {
  const Texture* texture = nullptr;
  std::uint16_t instance = 0;
  core::SemanticClass semantic_class = core::SemanticClass::kNone;
  bool dynamic = false;  // the object moves at the rendered frame (see scene.h)
};

// A planar rectangle origin + s * axis_u + t * axis_v, s in [0, size_u], t in [0, size_v], with
// orthonormal axes. It is one-sided: visible only from the side its normal axis_u x axis_v
// points to, so closed boxes need no hidden faces drawn. (s, t) are its texture coordinates.
struct Rect {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_u = Eigen::Vector3d::UnitX();
  Eigen::Vector3d axis_v = Eigen::Vector3d::UnitY();
  double size_u = 1.0;
  double size_v = 1.0;

  [[nodiscard]] Eigen::Vector3d normal() const { return axis_u.cross(axis_v); }
  [[nodiscard]] std::array<Eigen::Vector3d, 4> corners() const;
};

// An ellipsoid with orthonormal principal axes (columns of `axes`) and semi-axis lengths `radii`.
// Texture coordinates: s = (longitude about axis 2 + pi) * mean(radii[0], radii[1]),
// t = (1 + height along axis 2 / radii[2]) * radii[2], i.e. a texture wrapped around axis 2.
struct Ellipsoid {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d radii = Eigen::Vector3d::Ones();

  // Width and height (metres) of the texture that covers it once.
  [[nodiscard]] Eigen::Vector2d textureExtent() const;
  // The 8 corners of its bounding box.
  [[nodiscard]] std::array<Eigen::Vector3d, 8> boxCorners() const;
};

struct TexturedRect {
  Rect shape;
  SurfaceInfo surface;
};

struct TexturedEllipsoid {
  Ellipsoid shape;
  SurfaceInfo surface;
};

// Everything the renderer draws for one frame, in world coordinates.
struct RenderScene {
  std::vector<TexturedRect> rects;
  std::vector<TexturedEllipsoid> ellipsoids;
};

Rect transformed(const geometry::Pose& pose, const Rect& rect);
Ellipsoid transformed(const geometry::Pose& pose, const Ellipsoid& ellipsoid);

// The same rectangle seen from its other side (normal reversed, texture mirrored).
Rect flipped(const Rect& rect);

// The six faces of the axis-aligned box [low, high], normals pointing out, in the order
// +x, -x, +y, -y, +z, -z. On the side faces axis_v points up.
std::array<Rect, 6> boxFaces(const Eigen::Vector3d& low, const Eigen::Vector3d& high);

// Ellipsoid spanning the segment from `a` to `b` (its axis 2) with semi-axis `radius` across,
// overlapping each end by `overlap` metres so that joined limbs have no gaps.
Ellipsoid limbBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                      double overlap);

}  // namespace segslam::synth
