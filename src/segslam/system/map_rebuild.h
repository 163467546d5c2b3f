#pragma once

#include <filesystem>

#include "segslam/dense/map_builder.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/system/map_output.h"

namespace segslam::system {

struct MapRebuildOptions {
  dense::MapBuilderOptions map;
  // Dynamic masks of the keyframes: the dataset's mask.txt (true) or none.
  bool oracle_masks = false;
};

// Rebuilds <run_dir>/map from the run's KeyFrameTrajectory.txt and the dataset's images of those
// keyframes (matched by timestamp), e.g. with another voxel size, after the fact. Throws
// util::Error when the trajectory is missing or malformed, a keyframe has no frame in the
// dataset, or oracle masks are asked of a dataset without mask.txt.
MapSummary rebuildMap(const io::TumDataset& dataset, const std::filesystem::path& run_dir,
                      const MapRebuildOptions& options);

}  // namespace segslam::system
