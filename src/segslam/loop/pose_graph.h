#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "segslam/geometry/pose.h"

namespace segslam::loop {

struct PoseGraphNode {
  std::uint64_t id = 0;                              // the caller's, carried through
  geometry::Pose T_cw = geometry::Pose::Identity();  // world-to-camera
  bool fixed = false;
};

// A measured relative pose between two nodes: T_from_to = T_from_w * T_to_w^-1 (it maps `to`'s
// camera coordinates into `from`'s).
struct PoseGraphEdge {
  std::size_t from = 0;  // index into PoseGraph::nodes
  std::size_t to = 0;
  geometry::Pose T_from_to = geometry::Pose::Identity();
  double weight = 1.0;
};

struct PoseGraph {
  std::vector<PoseGraphNode> nodes;
  std::vector<PoseGraphEdge> edges;
};

struct PoseGraphOptions {
  int iterations = 20;
};

// SE(3) pose-graph optimisation (Levenberg-Marquardt, Ceres): minimises, over the non-fixed node
// poses, the sum of weight * |[t_error; 2 q_error.vec]|^2 where q_error and t_error are the
// rotation and translation of the difference between each edge's measured and estimated relative
// pose. RGB-D sees metric depth, so no scale is estimated. Updates the nodes in place and returns
// the solver's iterations. Throws std::invalid_argument on out-of-range node indices.
int optimisePoseGraph(PoseGraph& graph, const PoseGraphOptions& options = {});

}  // namespace segslam::loop
