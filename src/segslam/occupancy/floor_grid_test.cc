#include "segslam/occupancy/floor_grid.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "segslam/testing/test_support.h"

namespace segslam::occupancy {
namespace {

// A camera 1.2 m above a floor (z = 0, up = +z) looks along +x at a floor 3 m long, a box 0.5 m
// high at x = 2 and, in the first views, a person at x = 1 whom the masks mark.
Scan viewOfTheRoom(bool person) {
  Scan scan;
  scan.origin = Eigen::Vector3d(0.0, 0.0, 1.2);
  for (double x = 0.3; x <= 3.0; x += 0.02) {
    for (double y = -1.0; y <= 1.0; y += 0.02) {
      const bool behind_box = x > 1.9 && std::abs(y) < 0.3;
      const bool behind_person = person && x > 0.9 && std::abs(y) < 0.2;
      if (!behind_box && !behind_person) scan.static_ends.emplace_back(x, y, 0.0);
    }
  }
  for (double y = -0.3; y <= 0.3; y += 0.02) {
    for (double z = 0.0; z <= 0.5; z += 0.02) scan.static_ends.emplace_back(1.9, y, z);
  }
  if (person) {
    for (double y = -0.2; y <= 0.2; y += 0.02) {
      for (double z = 0.0; z <= 1.7; z += 0.02) scan.dynamic_ends.emplace_back(0.9, y, z);
    }
  }
  return scan;
}

std::uint8_t cellAt(const FloorGrid& grid, double x, double y) {
  const Eigen::Vector3d p(x, y, 0.0);
  const int col =
      static_cast<int>(std::floor((p.dot(grid.u_axis) - grid.origin.x()) / grid.resolution_m));
  const int row =
      grid.cells.rows - 1 -
      static_cast<int>(std::floor((p.dot(grid.v_axis) - grid.origin.y()) / grid.resolution_m));
  if (col < 0 || col >= grid.cells.cols || row < 0 || row >= grid.cells.rows) {
    return FloorGrid::kUnknown;
  }
  return grid.cells.at<std::uint8_t>(row, col);
}

TEST(FloorGrid, UpIsWhereTheCamerasImagesPointUp) {
  Eigen::Matrix3d level;  // camera x right, y down (world -z), z forward (world +x)
  level << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  EXPECT_TRUE(upFromCameras({level, level}).isApprox(Eigen::Vector3d::UnitZ()));
}

// The floor is found; the box is an obstacle; the person who walked through leaves free cells.
TEST(FloorGrid, ObstaclesAreWhatStandsOnTheFloorNotThePeopleWhoWalked) {
  OccupancyMap map;
  map.insert(viewOfTheRoom(true));
  map.insert(viewOfTheRoom(false));
  const FloorGrid grid = projectOntoFloor(map, Eigen::Vector3d::UnitZ());
  ASSERT_FALSE(grid.cells.empty());
  EXPECT_TRUE(grid.floor_found);
  EXPECT_NEAR(grid.floor_height_m, 0.0, 0.051);
  EXPECT_EQ(cellAt(grid, 1.9, 0.0), FloorGrid::kOccupied);  // the box
  EXPECT_EQ(cellAt(grid, 0.9, 0.0), FloorGrid::kFree);      // where the person stood
  EXPECT_EQ(cellAt(grid, 1.2, 0.6), FloorGrid::kFree);      // open floor
  EXPECT_EQ(cellAt(grid, 2.6, 0.0), FloorGrid::kUnknown);   // hidden behind the box
  int occupied = 0;
  for (int row = 0; row < grid.cells.rows; ++row) {
    for (int col = 0; col < grid.cells.cols; ++col) {
      occupied += grid.cells.at<std::uint8_t>(row, col) == FloorGrid::kOccupied ? 1 : 0;
    }
  }
  EXPECT_LE(occupied, 2 * 14);  // the box's footprint, 0.6 m wide, a cell or two deep
}

TEST(FloorGrid, TheBandDecidesWhatIsAnObstacle) {
  OccupancyMap map;
  map.insert(viewOfTheRoom(false));
  FloorGridOptions above_the_box;
  above_the_box.band_min_m = 0.6;
  const FloorGrid grid = projectOntoFloor(map, Eigen::Vector3d::UnitZ(), above_the_box);
  EXPECT_NE(cellAt(grid, 1.9, 0.0), FloorGrid::kOccupied);
}

// map_server reads the image as (255 - value) / 255: 0 is occupied (> 0.65), 254 free
// (< 0.196), 205 unknown (0.196...); the YAML names the image beside it.
TEST(FloorGrid, MapServerFilesHoldTheGridAndItsPlace) {
  const segslam::testing::ScopedTempDir dir;
  OccupancyMap map;
  map.insert(viewOfTheRoom(false));
  const FloorGrid grid = projectOntoFloor(map, Eigen::Vector3d::UnitZ());
  writeMapServerFiles(grid, dir.path() / "grid.pgm", dir.path() / "grid.yaml");
  const cv::Mat image = cv::imread((dir.path() / "grid.pgm").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(image.type(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(image != grid.cells), 0);
  const std::string yaml = segslam::testing::fileContents(dir.path() / "grid.yaml");
  for (const std::string line : {"image: grid.pgm\n", "resolution: 0.050000\n", "negate: 0\n",
                                 "occupied_thresh: 0.65\n", "free_thresh: 0.196\n"}) {
    EXPECT_NE(yaml.find(line), std::string::npos) << line << " in\n" << yaml;
  }
  EXPECT_NE(
      yaml.find(fmt::format("origin: [{:.6f}, {:.6f}, 0.0]\n", grid.origin.x(), grid.origin.y())),
      std::string::npos)
      << yaml;
}

}  // namespace
}  // namespace segslam::occupancy
