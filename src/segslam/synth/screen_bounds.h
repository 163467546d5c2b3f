#pragma once

#include <Eigen/Core>
#include <array>
#include <span>

#include "segslam/core/camera.h"

namespace segslam::synth {

// An inclusive range of pixel columns and rows.
struct PixelBox {
  int u0 = 0;
  int u1 = -1;
  int v0 = 0;
  int v1 = -1;

  [[nodiscard]] bool empty() const { return u1 < u0 || v1 < v0; }
};

using Edge = std::array<int, 2>;

// The pixels whose centres may see a convex polyhedron or polygon, given by its vertices in the
// camera frame and its edges: the image bounds of the part in front of the plane z = near_z
// (vertices in front, plus the points where edges cross that plane), grown to whole pixels and
// clipped to the image. Empty when nothing is in front or all lies outside the image.
PixelBox screenBounds(std::span<const Eigen::Vector3d> vertices, std::span<const Edge> edges,
                      const core::Camera& camera, double near_z);

// Edges of a quadrilateral with vertices 0-1-2-3 and of a box whose vertex i has the corner
// bits (x: i & 1, y: i & 2, z: i & 4).
std::span<const Edge> quadEdges();
std::span<const Edge> boxEdges();

}  // namespace segslam::synth
