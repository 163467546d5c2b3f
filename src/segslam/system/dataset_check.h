#pragma once

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "segslam/io/tum_dataset.h"

namespace segslam::system {

// What a full pass over a dataset's images found. Until tracking exists, this is what
// `segslam run` produces: proof that every frame loads and agrees with the camera settings.
struct DatasetCheck {
  std::size_t frames = 0;            // checked, skipped ones included
  std::size_t skipped_frames = 0;    // with a damaged image; the statistics below leave them out
  double duration_s = 0.0;           // last minus first colour timestamp
  double mean_frame_rate = 0.0;      // frames per second of the recording
  double max_rgb_depth_gap_s = 0.0;  // worst colour/depth timestamp difference after association
  double valid_depth_share = 0.0;    // share of pixels with a depth measurement
  double min_depth_m = 0.0;
  double max_depth_m = 0.0;
  std::size_t frames_with_dynamic_pixels = 0;  // only when the dataset has masks
  double mean_dynamic_share = 0.0;             // only when the dataset has masks
  // Listed colour and depth images that the folder lacks (io::TumDataset::absentImages).
  std::vector<io::AbsentImage> absent_images;
  io::GroundTruthFrame ground_truth_frame = io::GroundTruthFrame::kCamera;
  std::size_t ground_truth_poses = 0;
  std::size_t frames_with_ground_truth = 0;  // frames whose timestamp associates to a GT pose
};

// Loads every frame and gathers the statistics above. A frame with a damaged image is skipped with
// a warning, as `run` skips it; util::Error when more than half are (io::DamagedFrames) and at
// the first other bad frame. `on_frame` is called after each frame, for progress display.
DatasetCheck checkDataset(const io::TumDataset& dataset, std::size_t max_frames,
                          const std::function<void()>& on_frame);

nlohmann::json toJson(const DatasetCheck& check);

}  // namespace segslam::system
