#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "segslam/core/trajectory.h"
#include "segslam/dense/map_builder.h"
#include "segslam/system/occupancy_output.h"

namespace segslam::system {

struct MapSummary {
  std::size_t keyframes = 0;
  std::size_t static_points = 0;
  std::size_t dynamic_points = 0;
  std::size_t objects = 0;
  std::size_t earlier_points_removed = 0;  // of a loaded map's dense map, seen through
  dense::MapTimings timings;
  double build_seconds = 0.0;  // waiting for that thread, assembling, cleaning, writing
  std::optional<OccupancySummary> occupancy;

  // CPU time spent on the keyframe clouds (mostly on the map thread, beside tracking).
  [[nodiscard]] double keyFrameSeconds() const {
    return timings.back_projection + timings.keyframe_voxels;
  }
};

// Builds the map from the keyframe poses and writes it into `folder` (see dense::writeDenseMap),
// with the occupancy map of the same keyframes unless `occupancy.build` is off.
MapSummary buildAndWriteMap(dense::MapBuilder& builder, const core::Trajectory& keyframe_poses,
                            const std::filesystem::path& folder,
                            const OccupancyOutputOptions& occupancy);

nlohmann::json toJson(const MapSummary& summary);

double secondsSince(std::chrono::steady_clock::time_point start);

}  // namespace segslam::system
