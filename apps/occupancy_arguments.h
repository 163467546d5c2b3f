#pragma once

#include <CLI/CLI.hpp>

#include "segslam/system/occupancy_output.h"

namespace segslam::apps {

// --occupancy/--no-occupancy, --occupancy-resolution, --occupancy-max-range and --floor-band,
// shared by `run` and `map`.
void addOccupancyOptions(CLI::App& command, system::OccupancyOutputOptions& options);

// The line `run` and `map` print about the occupancy map.
void printOccupancySummary(const system::OccupancySummary& summary);

}  // namespace segslam::apps
