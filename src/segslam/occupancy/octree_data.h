#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace segslam::occupancy {

// The extent of the node data of an OctoMap binary octree (.bt after its `data` line), as
// OccupancyOcTreeBase::writeBinaryData lays it out: the root and every inner node as two bytes,
// two bits per child (01 occupied leaf, 10 free leaf, 11 inner node, 00 none), the inner
// children's own bytes following depth first.
struct OctreeDataExtent {
  std::size_t nodes = 0;  // the root and every child, as OcTree::size() counts them
  std::size_t bytes = 0;  // where the node data ends; what follows is not the tree's
};

struct OctreeDataCheck {
  std::optional<OctreeDataExtent> extent;  // set when the data is a whole tree
  std::string problem;                     // otherwise what is wrong with it
  std::size_t nodes_read = 0;              // nodes before the data ended or went wrong
};

// Walks the node data without building the tree. OctoMap's own reader recurses once per inner
// node with no depth limit and, where the data ends early, reads on with uninitialised child
// bits: a cut or damaged file could take it into unbounded recursion (a stack overflow). Only
// data this check accepts is handed to it. `max_depth`: the tree's levels (OcTree: 16).
[[nodiscard]] OctreeDataCheck checkOctreeData(std::string_view data, unsigned max_depth);

}  // namespace segslam::occupancy
