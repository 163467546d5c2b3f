#include "segslam/occupancy/floor_grid.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <optional>

#include "segslam/util/error.h"

namespace segslam::occupancy {

namespace {

// A floor is a layer holding this many times the median layer's occupied voxels, and at least
// this many: a plane the camera looked down on, against walls spread over every height.
constexpr double kFloorLayerRatio = 3.0;
constexpr int kFloorLayerMinVoxels = 50;

struct GridFrame {
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  Eigen::Vector3d up;
};

GridFrame frameFor(const Eigen::Vector3d& up_direction) {
  GridFrame frame;
  frame.up = up_direction.normalized();
  // u: the world's x axis laid onto the floor (its y axis when x points up).
  Eigen::Vector3d u = Eigen::Vector3d::UnitX() - frame.up.x() * frame.up;
  if (u.norm() < 0.3) u = Eigen::Vector3d::UnitY() - frame.up.y() * frame.up;
  frame.u = u.normalized();
  frame.v = frame.up.cross(frame.u);
  return frame;
}

// The height of the floor's voxels along `up`, or nothing when no layer stands out.
std::optional<double> floorHeight(const std::vector<double>& heights, double resolution) {
  std::map<long, int> layers;
  for (double h : heights) ++layers[std::lround(h / resolution)];
  std::vector<int> counts;
  for (const auto& [layer, count] : layers) counts.push_back(count);
  std::nth_element(counts.begin(), counts.begin() + counts.size() / 2, counts.end());
  const double median = counts[counts.size() / 2];
  const long lowest = layers.begin()->first;
  const long highest = layers.rbegin()->first;
  for (const auto& [layer, count] : layers) {
    // Only the lower half of the heights seen: a ceiling or a table top is not the floor.
    if (2 * (layer - lowest) > highest - lowest) break;
    if (count >= kFloorLayerMinVoxels && count >= kFloorLayerRatio * median) {
      return static_cast<double>(layer) * resolution;
    }
  }
  return std::nullopt;
}

}  // namespace

Eigen::Vector3d upFromCameras(const std::vector<Eigen::Matrix3d>& camera_to_world_rotations) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& rotation : camera_to_world_rotations) sum -= rotation.col(1);
  if (sum.norm() < 1e-9) return Eigen::Vector3d::UnitZ();
  return sum.normalized();
}

FloorGrid projectOntoFloor(const OccupancyMap& map, const Eigen::Vector3d& up,
                           const FloorGridOptions& options) {
  const GridFrame frame = frameFor(up);
  const double resolution = map.resolution();
  FloorGrid grid;
  grid.resolution_m = resolution;
  grid.u_axis = frame.u;
  grid.v_axis = frame.v;
  grid.up = frame.up;
  const auto occupied = map.occupiedVoxels();
  if (occupied.empty()) return grid;
  std::vector<double> heights;
  heights.reserve(occupied.size());
  for (const auto& p : occupied) heights.push_back(p.dot(frame.up));
  const auto floor = floorHeight(heights, resolution);
  grid.floor_found = floor.has_value();
  grid.floor_height_m = floor ? *floor : *std::min_element(heights.begin(), heights.end());

  const auto free = map.freeVoxels();
  const auto inBand = [&](const Eigen::Vector3d& p) {
    const double above = p.dot(frame.up) - grid.floor_height_m;
    return above >= options.band_min_m && above <= options.band_max_m;
  };
  Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY);
  Eigen::Vector2d high = Eigen::Vector2d::Constant(-INFINITY);
  const auto extend = [&](const std::vector<Eigen::Vector3d>& voxels) {
    for (const auto& p : voxels) {
      if (!inBand(p)) continue;
      const Eigen::Vector2d uv(p.dot(frame.u), p.dot(frame.v));
      low = low.cwiseMin(uv);
      high = high.cwiseMax(uv);
    }
  };
  extend(occupied);
  extend(free);
  if (!(low.x() <= high.x())) return grid;
  grid.origin = low - Eigen::Vector2d::Constant(resolution / 2.0);
  const int cols = static_cast<int>(std::floor((high.x() - grid.origin.x()) / resolution)) + 1;
  const int rows = static_cast<int>(std::floor((high.y() - grid.origin.y()) / resolution)) + 1;
  grid.cells = cv::Mat(rows, cols, CV_8UC1, cv::Scalar(FloorGrid::kUnknown));
  const auto mark = [&](const std::vector<Eigen::Vector3d>& voxels, std::uint8_t value) {
    for (const auto& p : voxels) {
      if (!inBand(p)) continue;
      const int col = static_cast<int>(std::floor((p.dot(frame.u) - grid.origin.x()) / resolution));
      const int row =
          rows - 1 - static_cast<int>(std::floor((p.dot(frame.v) - grid.origin.y()) / resolution));
      if (col < 0 || col >= cols || row < 0 || row >= rows) continue;
      auto& cell = grid.cells.at<std::uint8_t>(row, col);
      if (value == FloorGrid::kOccupied || cell == FloorGrid::kUnknown) cell = value;
    }
  };
  mark(free, FloorGrid::kFree);
  mark(occupied, FloorGrid::kOccupied);
  return grid;
}

void writeMapServerFiles(const FloorGrid& grid, const std::filesystem::path& pgm,
                         const std::filesystem::path& yaml) {
  if (grid.cells.empty()) util::failAt(pgm, "the floor grid is empty: nothing to write");
  if (!cv::imwrite(pgm.string(), grid.cells)) util::failAt(pgm, "cannot write");
  std::ofstream out(yaml);
  out << fmt::format(
      "# segslam floor grid (map_server format). A world point p lies at\n"
      "#   (u, v) = (p . u_axis, p . v_axis), (p . up) - floor_height above the floor;\n"
      "#   u_axis: [{:.6f}, {:.6f}, {:.6f}]\n"
      "#   v_axis: [{:.6f}, {:.6f}, {:.6f}]\n"
      "#   up: [{:.6f}, {:.6f}, {:.6f}]\n"
      "#   floor_height: {:.4f}  (floor {})\n"
      "image: {}\n"
      "resolution: {:.6f}\n"
      "origin: [{:.6f}, {:.6f}, 0.0]\n"
      "negate: 0\n"
      "occupied_thresh: 0.65\n"
      "free_thresh: 0.196\n",
      grid.u_axis.x(), grid.u_axis.y(), grid.u_axis.z(), grid.v_axis.x(), grid.v_axis.y(),
      grid.v_axis.z(), grid.up.x(), grid.up.y(), grid.up.z(), grid.floor_height_m,
      grid.floor_found ? "found" : "not seen: heights from the lowest occupied voxel",
      pgm.filename().string(), grid.resolution_m, grid.origin.x(), grid.origin.y());
  if (!out.flush()) util::failAt(yaml, "cannot write");
}

}  // namespace segslam::occupancy
