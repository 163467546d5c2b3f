#include "segslam/system/occupancy_output.h"

#include <chrono>
#include <fstream>

#include "segslam/dense/ply_io.h"
#include "segslam/util/error.h"

namespace segslam::system {

namespace {

double secondsFrom(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

dense::LabelledCloud voxelCentres(const std::vector<Eigen::Vector3d>& voxels) {
  dense::LabelledCloud cloud;
  cloud.reserve(voxels.size());
  for (const auto& voxel : voxels) cloud.add(voxel.cast<float>(), {200, 200, 200});
  return cloud;
}

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// What the viewer needs besides the voxels and the grid's image: the grid's frame in the world.
void writeInfo(const std::filesystem::path& file, const OccupancySummary& summary,
               const occupancy::FloorGrid& grid) {
  nlohmann::json info = toJson(summary);
  info["grid"] = {{"image", occupancy::kFloorGridImage},
                  {"rows", grid.cells.rows},
                  {"cols", grid.cells.cols},
                  {"resolution_m", grid.resolution_m},
                  {"origin", {grid.origin.x(), grid.origin.y()}},
                  {"u_axis", vectorJson(grid.u_axis)},
                  {"v_axis", vectorJson(grid.v_axis)},
                  {"up", vectorJson(grid.up)},
                  {"floor_height_m", grid.floor_height_m}};
  std::ofstream out(file);
  out << info.dump(2) << "\n";
  if (!out.flush()) util::failAt(file, "cannot write");
}

}  // namespace

OccupancyOutput::OccupancyOutput(const OccupancyOutputOptions& options)
    : options_(options), map_(options.map) {
  if (options.earlier) map_.loadEarlier(*options.earlier);
}

void OccupancyOutput::scan(const Eigen::Vector3d& origin, const dense::LabelledCloud& static_points,
                           const dense::LabelledCloud& dynamic_points) {
  const auto start = std::chrono::steady_clock::now();
  map_.insert({origin, static_points.points, dynamic_points.points});
  seconds_ += secondsFrom(start);
}

OccupancySummary OccupancyOutput::write(const std::filesystem::path& folder,
                                        const core::Trajectory& keyframe_poses) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Eigen::Matrix3d> rotations;
  for (const auto& pose : keyframe_poses.poses()) rotations.push_back(pose.T_wc.linear());
  const auto grid =
      occupancy::projectOntoFloor(map_, occupancy::upFromCameras(rotations), options_.floor);
  map_.write(folder / occupancy::kOccupancyFile);
  if (!grid.cells.empty()) {
    occupancy::writeMapServerFiles(grid, folder / occupancy::kFloorGridImage,
                                   folder / occupancy::kFloorGridYaml);
  }
  const auto occupied = map_.occupiedVoxels();
  dense::writePly(folder / occupancy::kOccupiedVoxelsFile, voxelCentres(occupied));
  OccupancySummary summary;
  summary.resolution_m = map_.resolution();
  summary.occupied_voxels = occupied.size();
  summary.free_voxels = map_.counts().free;
  summary.continued_earlier = options_.earlier.has_value();
  summary.floor_found = grid.floor_found;
  summary.floor_height_m = grid.floor_height_m;
  summary.grid_rows = grid.cells.rows;
  summary.grid_cols = grid.cells.cols;
  writeInfo(folder / occupancy::kOccupancyInfoFile, summary, grid);
  summary.seconds = seconds_ + secondsFrom(start);
  return summary;
}

nlohmann::json toJson(const OccupancySummary& summary) {
  return {{"resolution_m", summary.resolution_m},
          {"occupied_voxels", summary.occupied_voxels},
          {"free_voxels", summary.free_voxels},
          {"continued_earlier", summary.continued_earlier},
          {"floor_found", summary.floor_found},
          {"floor_height_m", summary.floor_height_m},
          {"grid_rows", summary.grid_rows},
          {"grid_cols", summary.grid_cols},
          {"seconds", summary.seconds}};
}

}  // namespace segslam::system
