#include "occupancy_arguments.h"

#include <fmt/format.h>

#include <vector>

namespace segslam::apps {

void addOccupancyOptions(CLI::App& command, system::OccupancyOutputOptions& options) {
  command.add_flag("--occupancy,!--no-occupancy", options.build,
                   "Build the occupancy map with the dense map: map/occupancy.bt (OctoMap) and "
                   "the floor grid map/occupancy_2d.pgm + .yaml (map_server) (default on)");
  command
      .add_option("--occupancy-resolution", options.map.resolution_m,
                  "Voxel edge of the occupancy map and cell of the floor grid (metres)")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1.0));
  command
      .add_option("--occupancy-max-range", options.map.max_range_m,
                  "Rays are cast this far at most (metres; 0 = no limit)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command
      .add_option_function<std::vector<double>>(
          "--floor-band",
          [&options](const std::vector<double>& band) {
            if (band[0] >= band[1]) {
              throw CLI::ValidationError("--floor-band", "MIN must be below MAX");
            }
            options.floor.band_min_m = band[0];
            options.floor.band_max_m = band[1];
          },
          "Heights above the floor whose occupied voxels are obstacles in the floor grid "
          "(metres, MIN,MAX; default 0.1,1.8)")
      ->expected(2)
      ->delimiter(',')
      ->type_name("MIN,MAX");
}

void printOccupancySummary(const system::OccupancySummary& s) {
  fmt::print(
      "  occupancy  {} occupied and {} free voxels of {:.2f} m{}; floor grid {} x {} cells, "
      "floor {} ({:.1f} s)\n",
      s.occupied_voxels, s.free_voxels, s.resolution_m,
      s.continued_earlier ? ", carried on from the loaded session's" : "", s.grid_cols, s.grid_rows,
      s.floor_found ? "found" : "not seen (heights from the lowest voxel)", s.seconds);
}

}  // namespace segslam::apps
