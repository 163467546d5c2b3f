#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

// Whether points of this core::SemanticClass id can make a map object: not unknown, and not the
// room itself (wall, floor, ceiling), which a user does not pick as an object.
bool isObjectLabel(std::uint8_t label);

// The points of one object label that hang together in one keyframe's cloud.
struct LabelSegment {
  std::uint8_t label = 0;
  std::uint16_t instance = 0;        // the instance id of its points (0 = none)
  std::vector<std::size_t> indices;  // into the cloud, ascending
  std::vector<std::uint64_t> cells;  // packed cells (voxel_key.h) it occupies, ascending
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  Eigen::Vector3f min = Eigen::Vector3f::Zero();  // axis-aligned bounds of its points
  Eigen::Vector3f max = Eigen::Vector3f::Zero();
};

// Distance between the bounds of two segments (0 when they overlap).
float boundsGap(const LabelSegment& a, const LabelSegment& b);

// Splits the object-labelled points of `cloud` into segments: per label and instance id (when the
// segmentation gives them), points in the same or touching (26-neighbour) cells of edge
// `cell_size` are connected. A cell grid rather than a
// radius search: a keyframe cloud of 50 000 points is split in a few milliseconds. Segments of
// fewer than `min_points` points are left out (stray labels on an object's edge). Ordered by
// label, instance, then by their smallest point index.
std::vector<LabelSegment> segmentByLabel(const LabelledCloud& cloud, double cell_size,
                                         std::size_t min_points);

}  // namespace segslam::dense
