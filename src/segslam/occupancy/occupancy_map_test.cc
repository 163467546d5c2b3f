#include "segslam/occupancy/occupancy_map.h"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::occupancy {
namespace {

// The ends of rays from the origin onto an axis-aligned rectangle at depth z (x in [x0, x1], y in
// [y0, y1]), one every `step` metres.
std::vector<Eigen::Vector3f> rectangle(double x0, double x1, double y0, double y1, double z,
                                       double step = 0.02) {
  std::vector<Eigen::Vector3f> ends;
  for (double x = x0; x <= x1 + 1e-9; x += step) {
    for (double y = y0; y <= y1 + 1e-9; y += step) {
      ends.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
    }
  }
  return ends;
}

using State = VoxelState;

State stateAt(const OccupancyMap& map, double x, double y, double z) {
  return occupancy::stateAt(map.tree(), Eigen::Vector3d(x, y, z));
}

// A wall 3 m in front of the camera; a person stands 1.5 m in front of it in the first views.
Scan viewOfTheWall(bool person_in_front) {
  Scan scan;
  scan.origin = Eigen::Vector3d(0.0, 0.0, 0.0);
  for (const auto& end : rectangle(-1.0, 1.0, -0.5, 0.5, 3.0)) {
    const bool hidden = person_in_front && std::abs(end.x()) < 0.25;
    if (!hidden) scan.static_ends.push_back(end);
  }
  if (person_in_front) scan.dynamic_ends = rectangle(-0.12, 0.12, -0.5, 0.5, 1.5);
  return scan;
}

TEST(OccupancyMap, RaysMakeSpaceFreeUpToTheSurfaceTheyEndOn) {
  OccupancyMap map;
  map.insert(viewOfTheWall(false));
  EXPECT_EQ(stateAt(map, 0.5, 0.0, 3.0), State::kOccupied);
  EXPECT_EQ(stateAt(map, 0.5, 0.0, 1.5), State::kFree);
  EXPECT_EQ(stateAt(map, 0.5, 0.0, 3.5), State::kUnknown);  // behind the wall
  EXPECT_EQ(stateAt(map, 0.0, 2.0, 1.5), State::kUnknown);  // out of view
  const auto counts = map.counts();
  EXPECT_GT(counts.occupied, 300u);
  EXPECT_GT(counts.free, counts.occupied);
  EXPECT_EQ(map.occupiedVoxels().size(), counts.occupied);
}

// Where a person walked the map says free: the rays up to him clear space, he himself is never
// occupied, and once he has gone the wall behind him is seen.
TEST(OccupancyMap, APersonWalkingThroughLeavesFreeSpaceNotAnObstacle) {
  OccupancyMap map;
  map.insert(viewOfTheWall(true));
  EXPECT_EQ(stateAt(map, 0.0, 0.0, 1.5), State::kUnknown);  // the person: not occupied
  EXPECT_EQ(stateAt(map, 0.0, 0.0, 1.0), State::kFree);     // in front of him
  EXPECT_EQ(stateAt(map, 0.0, 0.0, 3.0), State::kUnknown);  // the wall he hides
  map.insert(viewOfTheWall(false));
  EXPECT_EQ(stateAt(map, 0.0, 0.0, 1.5), State::kFree);
  EXPECT_EQ(stateAt(map, 0.0, 0.0, 3.0), State::kOccupied);
  for (const auto& voxel : map.occupiedVoxels()) EXPECT_GT(voxel.z(), 2.9);
}

TEST(OccupancyMap, EndsBeyondTheMaximumRangeClearTheRayUpToItOnly) {
  OccupancyOptions options;
  options.max_range_m = 2.0;
  OccupancyMap map(options);
  map.insert(viewOfTheWall(false));
  EXPECT_EQ(map.counts().occupied, 0u);
  EXPECT_EQ(stateAt(map, 0.0, 0.0, 1.8), State::kFree);
  EXPECT_EQ(stateAt(map, 0.0, 0.0, 2.5), State::kUnknown);
}

// What OctoMap's own tools read: the .bt read back has the same occupied voxels.
TEST(OccupancyMap, WritesAnOctomapBinaryTreeThatReadsBack) {
  const segslam::testing::ScopedTempDir dir;
  OccupancyMap map;
  map.insert(viewOfTheWall(false));
  map.write(dir.path() / "occupancy.bt");
  const auto tree = readOctree(dir.path() / "occupancy.bt");
  EXPECT_NEAR(tree->getResolution(), 0.05, 1e-12);
  std::size_t occupied = 0;
  for (const auto& voxel : map.occupiedVoxels()) {
    const auto* node = tree->search(voxel.x(), voxel.y(), voxel.z());
    occupied += node != nullptr && tree->isNodeOccupied(node) ? 1 : 0;
  }
  EXPECT_EQ(occupied, map.counts().occupied);
}

// A session that loads an earlier one's map: a box moved since leaves its old place free after
// a few views of it, and shows up where it stands now.
TEST(OccupancyMap, AnEarlierSessionsMapCarriesOnAndMovedThingsChangePlace) {
  const segslam::testing::ScopedTempDir dir;
  const auto viewWithBoxAt = [](double box_x) {
    Scan scan = viewOfTheWall(false);
    std::erase_if(scan.static_ends,
                  [&](const Eigen::Vector3f& end) { return std::abs(end.x() - box_x) < 0.2; });
    for (const auto& end : rectangle(box_x - 0.15, box_x + 0.15, -0.5, 0.5, 2.0)) {
      scan.static_ends.push_back(end);
    }
    return scan;
  };
  OccupancyMap first;
  for (int view = 0; view < 5; ++view) first.insert(viewWithBoxAt(-0.5));
  ASSERT_EQ(stateAt(first, -0.5, 0.0, 2.0), State::kOccupied);
  first.write(dir.path() / "first.bt");

  OccupancyMap second;
  second.loadEarlier(dir.path() / "first.bt");
  EXPECT_EQ(stateAt(second, -0.5, 0.0, 2.0), State::kOccupied);  // before it looks
  EXPECT_EQ(stateAt(second, 0.8, 0.0, 3.0), State::kOccupied);
  for (int view = 0; view < 3; ++view) second.insert(viewWithBoxAt(0.5));
  EXPECT_EQ(stateAt(second, -0.5, 0.0, 2.0), State::kFree);
  EXPECT_EQ(stateAt(second, 0.5, 0.0, 2.0), State::kOccupied);
  EXPECT_EQ(stateAt(second, 0.8, 0.0, 3.0), State::kOccupied);  // the wall stays
}

TEST(OccupancyMap, BadFilesAreErrorsNamingThem) {
  const segslam::testing::ScopedTempDir dir;
  OccupancyMap map;
  const auto missing = dir.path() / "missing.bt";
  try {
    map.loadEarlier(missing);
    ADD_FAILURE() << "expected a util::Error";
  } catch (const util::Error& e) {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": file not found");
  }
  const auto text = dir.path() / "text.bt";
  std::ofstream(text) << "not an octree\n";
  try {
    map.loadEarlier(text);
    ADD_FAILURE() << "expected a util::Error";
  } catch (const util::Error& e) {
    EXPECT_EQ(std::string(e.what()), text.string() + ": not an OctoMap binary occupancy map (.bt)");
  }
  const auto cut = dir.path() / "cut.bt";
  map.insert(viewOfTheWall(false));
  map.write(cut);
  std::filesystem::resize_file(cut, std::filesystem::file_size(cut) - 40);
  try {
    (void)readOctree(cut);
    ADD_FAILURE() << "expected a util::Error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find(cut.string() + ": its data is cut short or damaged ("),
              std::string::npos)
        << e.what();
  }
  OccupancyOptions coarse;
  coarse.resolution_m = 0.1;
  OccupancyMap other(coarse);
  other.insert(viewOfTheWall(false));
  other.write(dir.path() / "coarse.bt");
  try {
    map.loadEarlier(dir.path() / "coarse.bt");
    ADD_FAILURE() << "expected a util::Error";
  } catch (const util::Error& e) {
    EXPECT_EQ(std::string(e.what()), (dir.path() / "coarse.bt").string() +
                                         ": an occupancy map of 0.1 m voxels, not 0.05 m");
  }
}

// A node stream of inner nodes only, as deep as its bytes go: OctoMap's reader would recurse
// once per node (two million deep here) until the stack overflows.
TEST(OccupancyMap, ANodeStreamDeeperThanAnOctreeIsAnErrorNotACrash) {
  const segslam::testing::ScopedTempDir dir;
  const auto deep = dir.path() / "deep.bt";
  {
    std::ofstream out(deep, std::ios::binary);
    out << "# Octomap OcTree binary file\nid OcTree\nsize 9\nres 0.05\ndata\n"
        << std::string(4u << 20, '\xff');
  }
  try {
    (void)readOctree(deep);
    ADD_FAILURE() << "expected a util::Error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find(deep.string() + ": its data is cut short or damaged "
                                                         "(inner nodes deeper than the tree's "
                                                         "16 levels"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace segslam::occupancy
