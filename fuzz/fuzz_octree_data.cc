// occupancy::checkOctreeData accepts only node data that OctoMap's reader (which recurses once per
// inner node, unchecked) reads back as a tree of exactly the nodes the check counted, within its
// bytes; whatever it refuses says why.

#include <octomap/OcTree.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz_check.h"
#include "segslam/occupancy/octree_data.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  using segslam::fuzz::check;
  const std::string data(reinterpret_cast<const char*>(bytes), size);
  octomap::OcTree tree(0.05);
  const auto result = segslam::occupancy::checkOctreeData(data, tree.getTreeDepth());
  if (!result.extent) {
    check(!result.problem.empty(), "refused data says what is wrong with it");
    return 0;
  }
  check(result.extent->bytes <= size && result.extent->bytes % 2 == 0,
        "the tree's bytes lie within the data, two a node");
  std::istringstream nodes(data.substr(0, result.extent->bytes));
  tree.readBinaryData(nodes);
  check(static_cast<bool>(nodes), "OctoMap reads the accepted bytes without running out");
  check(nodes.peek() == std::char_traits<char>::eof(), "OctoMap reads all the accepted bytes");
  check(tree.size() == result.extent->nodes, "OctoMap's tree has the nodes the check counted");
  return 0;
}
