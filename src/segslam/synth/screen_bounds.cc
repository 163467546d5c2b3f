#include "segslam/synth/screen_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace segslam::synth {

namespace {

constexpr std::array<Edge, 4> kQuadEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
constexpr std::array<Edge, 12> kBoxEdges{{{0, 1},
                                          {2, 3},
                                          {4, 5},
                                          {6, 7},
                                          {0, 2},
                                          {1, 3},
                                          {4, 6},
                                          {5, 7},
                                          {0, 4},
                                          {1, 5},
                                          {2, 6},
                                          {3, 7}}};

// Running bounds of projected points in pixel coordinates.
struct Extent {
  double u_min = std::numeric_limits<double>::infinity();
  double u_max = -std::numeric_limits<double>::infinity();
  double v_min = std::numeric_limits<double>::infinity();
  double v_max = -std::numeric_limits<double>::infinity();

  void add(const Eigen::Vector3d& p, const core::Camera& camera) {
    const double u = camera.fx * p.x() / p.z() + camera.cx;
    const double v = camera.fy * p.y() / p.z() + camera.cy;
    u_min = std::min(u_min, u);
    u_max = std::max(u_max, u);
    v_min = std::min(v_min, v);
    v_max = std::max(v_max, v);
  }
  [[nodiscard]] bool empty() const { return !(u_min <= u_max); }
};

// Clamps before converting so that points projected far outside cannot overflow an int.
int clampedFloor(double value, int high) {
  return static_cast<int>(std::floor(std::clamp(value, -1.0, high + 1.0)));
}

int clampedCeil(double value, int high) {
  return static_cast<int>(std::ceil(std::clamp(value, -1.0, high + 1.0)));
}

}  // namespace

PixelBox screenBounds(std::span<const Eigen::Vector3d> vertices, std::span<const Edge> edges,
                      const core::Camera& camera, double near_z) {
  Extent extent;
  for (const auto& p : vertices) {
    if (p.z() >= near_z) extent.add(p, camera);
  }
  for (const auto& [a, b] : edges) {
    const Eigen::Vector3d& pa = vertices[a];
    const Eigen::Vector3d& pb = vertices[b];
    if ((pa.z() < near_z) == (pb.z() < near_z)) continue;
    const double along = (near_z - pa.z()) / (pb.z() - pa.z());
    Eigen::Vector3d crossing = pa + along * (pb - pa);
    crossing.z() = near_z;
    extent.add(crossing, camera);
  }
  if (extent.empty()) return {};
  PixelBox box;
  box.u0 = std::max(0, clampedFloor(extent.u_min, camera.width));
  box.u1 = std::min(camera.width - 1, clampedCeil(extent.u_max, camera.width));
  box.v0 = std::max(0, clampedFloor(extent.v_min, camera.height));
  box.v1 = std::min(camera.height - 1, clampedCeil(extent.v_max, camera.height));
  return box;
}

std::span<const Edge> quadEdges() { return kQuadEdges; }

std::span<const Edge> boxEdges() { return kBoxEdges; }

}  // namespace segslam::synth
