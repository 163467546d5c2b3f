#include "segslam/occupancy/octree_data.h"

#include <fmt/format.h>

#include <array>
#include <vector>

namespace segslam::occupancy {

namespace {

struct NodeChildren {
  int existing = 0;
  int inner = 0;
};

// The children one node's two bytes announce: per child a low bit and a high bit.
NodeChildren childrenOf(unsigned char first_four, unsigned char last_four) {
  NodeChildren children;
  for (const unsigned char bits : std::array{first_four, last_four}) {
    for (int child = 0; child < 4; ++child) {
      const unsigned code = (bits >> (2 * child)) & 0x3u;
      children.existing += code != 0;
      children.inner += code == 0x3u;
    }
  }
  return children;
}

}  // namespace

OctreeDataCheck checkOctreeData(std::string_view data, unsigned max_depth) {
  OctreeDataCheck check;
  std::size_t at = 0;
  // Inner children still to read, one entry per open level below the root.
  std::vector<int> pending;
  check.nodes_read = 1;  // the root
  while (true) {
    if (at + 2 > data.size()) {
      check.problem = "cut short";
      return check;
    }
    const NodeChildren children =
        childrenOf(static_cast<unsigned char>(data[at]), static_cast<unsigned char>(data[at + 1]));
    at += 2;
    check.nodes_read += static_cast<std::size_t>(children.existing);
    if (children.inner > 0) pending.push_back(children.inner);
    while (!pending.empty() && pending.back() == 0) pending.pop_back();
    if (pending.empty()) break;
    --pending.back();
    // The next node read is an inner node at level pending.size(); its children lie one deeper.
    if (pending.size() >= max_depth) {
      check.problem = fmt::format("inner nodes deeper than the tree's {} levels", max_depth);
      return check;
    }
  }
  check.extent = OctreeDataExtent{check.nodes_read, at};
  return check;
}

}  // namespace segslam::occupancy
