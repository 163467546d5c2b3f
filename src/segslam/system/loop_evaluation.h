#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "segslam/eval/loop_ground_truth.h"
#include "segslam/eval/precision_recall.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/place/place_descriptor_method.h"
#include "segslam/system/mask_source.h"

namespace segslam::system {

// Fresh place-recognition methods with no image added: one set is built per mask source.
using PlaceMethodFactory =
    std::function<std::vector<std::unique_ptr<place::PlaceDescriptorMethod>>()>;

struct LoopEvaluationOptions {
  std::size_t every = 10;  // every Nth frame (with a ground-truth pose) is a database image
  eval::LoopThresholds thresholds;
  // Each source other than none adds a union-mask column; without masks is always scored.
  std::vector<MaskSourceOptions> masks;
};

// One method's precision-recall curve with one kind of mask ("none" = compared without masks).
struct LoopMethodResult {
  std::string method;
  std::string masks;
  eval::PrCurve curve;
};

struct LoopEvaluation {
  std::filesystem::path dataset;
  std::size_t every = 0;
  eval::LoopThresholds thresholds;
  std::vector<double> timestamps;  // of the database images
  std::vector<eval::LoopPair> pairs;
  std::size_t loop_pairs = 0;
  std::vector<std::string> mask_columns;  // "none", then the union-mask sources
  std::vector<LoopMethodResult> results;
};

// Scores every pair of database images at least min_gap_s apart with every method, without
// masks and with the union mask of each mask source, against loop labels from the ground-truth
// poses. Throws util::Error when the dataset has no ground truth or no ground-truth loop.
LoopEvaluation evaluateLoops(const io::TumDataset& dataset, const LoopEvaluationOptions& options,
                             const PlaceMethodFactory& make_methods,
                             const std::function<void()>& on_frame);

nlohmann::json toJson(const LoopEvaluation& evaluation);
// Markdown: the settings, then a table of average precision per method and mask column.
std::string loopTableMarkdown(const LoopEvaluation& evaluation,
                              const std::vector<std::string>& notes);
// loops.md, loops.json and pr_curves.svg (one panel per mask column) in out_dir.
void writeLoopReport(const std::filesystem::path& out_dir, const LoopEvaluation& evaluation,
                     const std::vector<std::string>& notes);

}  // namespace segslam::system
