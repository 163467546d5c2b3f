#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "segslam/core/trajectory.h"
#include "segslam/dense/labelled_cloud.h"
#include "segslam/occupancy/floor_grid.h"
#include "segslam/occupancy/map_files.h"
#include "segslam/occupancy/occupancy_map.h"

namespace segslam::system {

struct OccupancyOutputOptions {
  bool build = true;
  occupancy::OccupancyOptions map;
  occupancy::FloorGridOptions floor;
  // An earlier session's occupancy map (map/occupancy.bt of the run that saved a loaded map
  // file): this run's keyframes carry it on.
  std::optional<std::filesystem::path> earlier;
};

struct OccupancySummary {
  double resolution_m = 0.0;
  std::size_t occupied_voxels = 0;
  std::size_t free_voxels = 0;
  bool continued_earlier = false;  // started from an earlier session's map
  bool floor_found = false;
  double floor_height_m = 0.0;
  int grid_rows = 0;
  int grid_cols = 0;
  double seconds = 0.0;  // ray casting, projecting and writing
};

// Builds the occupancy map from the keyframes' points as dense::MapBuilder::build hands them over
// (scan()), then writes it into a map folder (write()): occupancy.bt (OctoMap), the floor grid
// as map_server reads it (occupancy_2d.pgm, occupancy_2d.yaml), and for the viewer the occupied
// voxels' centres (occupancy_occupied.ply) and occupancy.json (counts, the grid's frame).
class OccupancyOutput {
 public:
  explicit OccupancyOutput(const OccupancyOutputOptions& options);

  void scan(const Eigen::Vector3d& origin, const dense::LabelledCloud& static_points,
            const dense::LabelledCloud& dynamic_points);
  // `keyframe_poses` tell which way is up (occupancy::upFromCameras).
  OccupancySummary write(const std::filesystem::path& folder,
                         const core::Trajectory& keyframe_poses);

  [[nodiscard]] const occupancy::OccupancyMap& map() const { return map_; }

 private:
  OccupancyOutputOptions options_;
  occupancy::OccupancyMap map_;
  double seconds_ = 0.0;
};

nlohmann::json toJson(const OccupancySummary& summary);

}  // namespace segslam::system
