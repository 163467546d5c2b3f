#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

#include "segslam/occupancy/occupancy_map.h"

namespace segslam::occupancy {

struct FloorGridOptions {
  // Obstacles are the occupied voxels this high above the floor (metres): above the floor itself
  // and its noise, up to what a robot's body reaches.
  double band_min_m = 0.1;
  double band_max_m = 1.8;
};

// A 2D occupancy grid on the floor, as ROS navigation plans on (map_server). Cell (row, col) of
// `cells` covers u in [origin.x + col * resolution, + resolution) and v in [origin.y +
// (rows - 1 - row) * resolution, + resolution): row 0 is the far v edge, as an image is drawn.
struct FloorGrid {
  cv::Mat cells;  // CV_8UC1: kOccupied, kFree or kUnknown
  double resolution_m = 0.05;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // (u, v) of the lower-left cell's corner
  // The grid's frame in the world: u, v along the floor, up away from it; world point p lies
  // at (u, v) = (p . u_axis, p . v_axis) and height (p . up) - floor_height above the floor.
  Eigen::Vector3d u_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d v_axis = Eigen::Vector3d::UnitY();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double floor_height_m = 0.0;
  // Whether a floor was seen; if not, heights count from the lowest occupied voxel.
  bool floor_found = false;

  static constexpr std::uint8_t kOccupied = 0;
  static constexpr std::uint8_t kFree = 254;
  static constexpr std::uint8_t kUnknown = 205;
};

// The world's up direction from where the cameras looked: the mean of the cameras' up axes (the
// image's -y), cameras being held and carried upright. `camera_to_world`: the keyframes' poses.
Eigen::Vector3d upFromCameras(const std::vector<Eigen::Matrix3d>& camera_to_world_rotations);

// Finds the floor (the lowest horizontal layer of occupied voxels that stands out from the walls'
// and furniture's, along `up`) and projects the map onto it: a cell is occupied when an occupied
// voxel lies in its column within the height band, free when a free one does and no occupied
// one, unknown otherwise. Empty cells when the map has no occupied voxel.
FloorGrid projectOntoFloor(const OccupancyMap& map, const Eigen::Vector3d& up,
                           const FloorGridOptions& options = {});

// The grid as map_server reads it: `pgm` (8-bit, 0 occupied, 254 free, 205 unknown) and `yaml`
// (image, resolution, origin, negate, occupied_thresh, free_thresh), with comments giving the
// grid's frame in the world. util::Error naming a file that cannot be written.
void writeMapServerFiles(const FloorGrid& grid, const std::filesystem::path& pgm,
                         const std::filesystem::path& yaml);

}  // namespace segslam::occupancy
