#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "segslam/eval/mask_metrics.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/system/mask_source.h"

namespace segslam::system {

struct MaskEvaluationOptions {
  MaskSourceOptions masks;
  std::size_t max_frames = std::numeric_limits<std::size_t>::max();
  int mask_dilation_px = 10;  // as SLAM dilates the mask before extraction (survival figure)
  int features = 1000;
  bool synchronous = false;  // network on the calling thread (reproducible)
  bool write_masks = false;  // predicted masks as masks/<timestamp>.png listed in mask.txt
  // A mask list (`timestamp path` per line, paths relative to the list) of pixels left out of the
  // scores where the ground truth is static: real objects of the dynamic classes that the ground
  // truth does not mark (the seated person in the background of the TUM walker frames).
  std::optional<std::filesystem::path> ignore_masks;
};

struct FrameMaskScores {
  double timestamp = 0.0;
  bool truth_dynamic = false;  // the ground truth marks something in this frame
  eval::MaskScores scores;
  eval::KeypointSurvival survival;
};

struct MaskEvaluationSummary {
  std::vector<FrameMaskScores> frames;
  std::size_t frames_with_dynamic = 0;
  // Means over the frames whose ground truth marks something.
  double mean_iou = 0.0;
  double mean_precision = 0.0;
  double mean_recall = 0.0;
  eval::MaskScores total;  // all pixels of all frames
  // All pixels of the frames whose ground truth marks something: the pooled (dataset-level)
  // IoU of segmentation benchmarks over the frames where an object is visible.
  eval::MaskScores total_where_dynamic;
  eval::KeypointSurvival survival;
};

// The summary of scored frames: means over the frames whose ground truth marks something, and
// the pixels pooled over all frames and over those frames.
MaskEvaluationSummary summariseMaskScores(std::vector<FrameMaskScores> frames);

// Runs a mask source over a dataset with ground-truth masks (mask.txt) and scores every frame:
// IoU, precision and recall of the predicted dynamic mask, and the share of keypoints on truly
// dynamic pixels that survive extraction with the predicted (dilated) mask. Writes
// mask_evaluation.csv (per frame) and mask_evaluation.json (summary) into out_dir, and with
// write_masks the predicted masks in the layout of a dataset's mask.txt.
// Throws util::Error when the dataset has no mask.txt.
MaskEvaluationSummary evaluateMasks(const io::TumDataset& dataset,
                                    const MaskEvaluationOptions& options,
                                    const std::filesystem::path& out_dir,
                                    const std::function<void()>& on_frame);

nlohmann::json toJson(const MaskEvaluationSummary& summary);

}  // namespace segslam::system
