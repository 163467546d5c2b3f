#pragma once

#include <filesystem>
#include <optional>

#include "segslam/dense/map_builder.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/system/map_output.h"

namespace segslam::system {

struct MapRebuildOptions {
  dense::MapBuilderOptions map;
  OccupancyOutputOptions occupancy;
  // Dynamic masks of the keyframes: the dataset's mask.txt (true) or none.
  bool oracle_masks = false;
  // With a model config: the network segments every keyframe itself (nothing is carried over
  // from other frames) and its dynamic mask and labels replace the dataset's.
  std::optional<std::filesystem::path> model_config;
  std::optional<std::filesystem::path> model_file;  // overrides the config's network file
};

// Rebuilds <run_dir>/map from the run's KeyFrameTrajectory.txt and the dataset's images of those
// keyframes (matched by timestamp), e.g. with another voxel size, after the fact. Throws
// util::Error when the trajectory is missing or malformed, a keyframe has no frame in the
// dataset, or oracle masks are asked of a dataset without mask.txt.
MapSummary rebuildMap(const io::TumDataset& dataset, const std::filesystem::path& run_dir,
                      const MapRebuildOptions& options);

}  // namespace segslam::system
