#include "segslam/occupancy/octree_data.h"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <sstream>
#include <string>

namespace segslam::occupancy {
namespace {

std::string nodeDataOf(const octomap::OcTree& tree) {
  std::ostringstream out;
  tree.writeBinaryData(out);
  return out.str();
}

octomap::OcTree aSmallTree() {
  octomap::OcTree tree(0.05);
  for (int i = 0; i < 20; ++i) {
    tree.updateNode(octomap::point3d(0.1f * static_cast<float>(i), 0.3f, 1.0f), true);
    tree.updateNode(octomap::point3d(0.1f * static_cast<float>(i), 0.0f, 0.5f), false);
  }
  return tree;
}

TEST(OctreeData, AWrittenTreeIsWholeWithOctomapsNodeCount) {
  const octomap::OcTree tree = aSmallTree();
  const std::string data = nodeDataOf(tree);
  const OctreeDataCheck check = checkOctreeData(data + "trailing", tree.getTreeDepth());
  ASSERT_TRUE(check.extent) << check.problem;
  EXPECT_EQ(check.extent->nodes, tree.size());
  EXPECT_EQ(check.extent->bytes, data.size());
}

TEST(OctreeData, DataThatEndsEarlyIsCutShort) {
  const octomap::OcTree tree = aSmallTree();
  const std::string data = nodeDataOf(tree);
  const OctreeDataCheck check =
      checkOctreeData(std::string_view(data).substr(0, data.size() - 3), tree.getTreeDepth());
  EXPECT_FALSE(check.extent);
  EXPECT_EQ(check.problem, "cut short");
  EXPECT_LT(check.nodes_read, tree.size());
}

TEST(OctreeData, InnerNodesBelowTheLastLevelAreDamage) {
  // Every child of every node inner: the 16th level of inner nodes is one too many.
  const OctreeDataCheck check = checkOctreeData(std::string(64, '\xff'), 16);
  EXPECT_FALSE(check.extent);
  EXPECT_EQ(check.problem, "inner nodes deeper than the tree's 16 levels");
  EXPECT_EQ(checkOctreeData(std::string(2, '\0'), 16).extent->nodes, 1u);  // the root alone
}

}  // namespace
}  // namespace segslam::occupancy
