#include "segslam/system/loop_evaluation.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>

#include "segslam/eval/closest_index.h"
#include "segslam/eval/svg_plot.h"
#include "segslam/util/error.h"

namespace segslam::system {

namespace {

struct DatabaseFrames {
  std::vector<std::size_t> indices;  // dataset frame indices
  std::vector<core::StampedPose> poses;
};

DatabaseFrames databaseFrames(const io::TumDataset& dataset, std::size_t every) {
  if (!dataset.groundTruth() || dataset.groundTruth()->empty()) {
    util::failAt(dataset.folder() / "groundtruth.txt",
                 "loop evaluation needs ground-truth poses, and the dataset has none");
  }
  const core::Trajectory& truth = *dataset.groundTruth();
  const std::vector<double> stamps = truth.timestamps();
  // The same tolerance as colour-depth association: a pose further away is another view.
  constexpr double kMaxPoseTimeDifference = 0.02;
  DatabaseFrames frames;
  for (std::size_t k = 0; k < dataset.size(); k += every) {
    const double t = dataset.frames()[k].timestamp;
    const std::size_t nearest = eval::findClosestIndex(stamps, t);
    if (std::abs(stamps[nearest] - t) > kMaxPoseTimeDifference) continue;
    frames.indices.push_back(k);
    frames.poses.push_back({t, truth[nearest].T_wc});
  }
  return frames;
}

bool needsEveryFrame(MaskSource source) {
  return source != MaskSource::kNone && source != MaskSource::kOracle;
}

place::PlaceImage placeImage(const io::RgbdFrame& frame, const cv::Mat& dynamic) {
  place::PlaceImage image;
  image.bgr = frame.rgb;
  if (!dynamic.empty()) image.static_mask = 255 - dynamic;
  return image;
}

using Methods = std::vector<std::unique_ptr<place::PlaceDescriptorMethod>>;

// Feeds the database images to fresh methods, with masks from `masks`.
Methods describeDatabase(const io::TumDataset& dataset, const DatabaseFrames& frames,
                         const MaskSourceOptions& masks, const PlaceMethodFactory& make_methods,
                         const std::function<void()>& on_frame) {
  Methods methods = make_methods();
  FrameMaskSource source(dataset, masks, /*synchronous=*/true);
  const std::size_t last = frames.indices.back();
  std::size_t next = 0;
  for (std::size_t k = 0; k <= last; ++k) {
    const bool in_database = frames.indices[next] == k;
    if (!in_database && !needsEveryFrame(masks.source)) continue;
    const io::RgbdFrame frame = dataset.loadFrame(k);
    const cv::Mat dynamic = source.dynamicMask(frame, k);
    if (!in_database) continue;
    const place::PlaceImage image = placeImage(frame, dynamic);
    for (auto& method : methods) method->add(image);
    ++next;
    if (on_frame) on_frame();
  }
  return methods;
}

eval::PrCurve score(const place::PlaceDescriptorMethod& method,
                    const std::vector<eval::LoopPair>& pairs, bool union_mask) {
  std::vector<eval::ScoredPair> scored;
  scored.reserve(pairs.size());
  for (const auto& pair : pairs) {
    scored.push_back({method.similarity(pair.i, pair.j, union_mask), pair.loop});
  }
  return eval::precisionRecall(scored);
}

std::string columnTitle(const std::string& masks) {
  return masks == "none" ? "no mask" : fmt::format("union mask ({})", masks);
}

std::vector<std::string> methodNames(const LoopEvaluation& evaluation) {
  std::vector<std::string> names;
  for (const auto& result : evaluation.results) {
    if (std::find(names.begin(), names.end(), result.method) == names.end()) {
      names.push_back(result.method);
    }
  }
  return names;
}

// The pooled variants of a layer are drawn in the colour of the layer's flattened one, dashed
// (union mask) or dotted (each image's own static area).
std::string baseMethodName(const std::string& method) {
  return method.substr(0, method.find(":pooled"));
}

std::string dashOf(const std::string& method) {
  if (method.ends_with(":pooled:static")) return "2,3";
  return method.ends_with(":pooled") ? "6,4" : "";
}

std::string formatAp(double value) {
  return std::isfinite(value) ? fmt::format("{:.3f}", value) : "n/a";
}

}  // namespace

LoopEvaluation evaluateLoops(const io::TumDataset& dataset, const LoopEvaluationOptions& options,
                             const PlaceMethodFactory& make_methods,
                             const std::function<void()>& on_frame) {
  const DatabaseFrames frames = databaseFrames(dataset, std::max<std::size_t>(options.every, 1));
  LoopEvaluation evaluation;
  evaluation.dataset = dataset.folder();
  evaluation.every = options.every;
  evaluation.thresholds = options.thresholds;
  for (const auto& pose : frames.poses) evaluation.timestamps.push_back(pose.timestamp);
  evaluation.pairs = eval::loopPairs(frames.poses, options.thresholds);
  for (const auto& pair : evaluation.pairs) evaluation.loop_pairs += pair.loop ? 1 : 0;
  if (evaluation.loop_pairs == 0) {
    util::failAt(dataset.folder() / "groundtruth.txt",
                 fmt::format("no ground-truth loop among {} pairs of {} images (translation < {} "
                             "m, rotation < {} deg, at least {} s apart)",
                             evaluation.pairs.size(), frames.poses.size(),
                             options.thresholds.max_translation_m,
                             options.thresholds.max_rotation_deg, options.thresholds.min_gap_s));
  }
  std::vector<MaskSourceOptions> passes;
  for (const auto& masks : options.masks) {
    if (masks.source != MaskSource::kNone) passes.push_back(masks);
  }
  if (passes.empty()) passes.emplace_back();
  evaluation.mask_columns.emplace_back("none");
  for (std::size_t p = 0; p < passes.size(); ++p) {
    const Methods methods = describeDatabase(dataset, frames, passes[p], make_methods, on_frame);
    const std::string masks = maskSourceName(passes[p].source);
    if (masks != "none") evaluation.mask_columns.push_back(masks);
    for (const auto& method : methods) {
      // Without masks every pass scores the same; the first one stands for all.
      if (p == 0)
        evaluation.results.push_back(
            {method->name(), "none", score(*method, evaluation.pairs, false)});
      if (masks != "none") {
        evaluation.results.push_back(
            {method->name(), masks, score(*method, evaluation.pairs, true)});
      }
    }
  }
  return evaluation;
}

nlohmann::json toJson(const LoopEvaluation& evaluation) {
  nlohmann::json results = nlohmann::json::array();
  for (const auto& result : evaluation.results) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& point : result.curve.points) {
      points.push_back({point.threshold, point.precision, point.recall});
    }
    results.push_back({{"method", result.method},
                       {"masks", result.masks},
                       {"average_precision", std::isfinite(result.curve.average_precision)
                                                 ? nlohmann::json(result.curve.average_precision)
                                                 : nlohmann::json(nullptr)},
                       {"curve_threshold_precision_recall", points}});
  }
  return {{"dataset", evaluation.dataset.string()},
          {"every", evaluation.every},
          {"max_translation_m", evaluation.thresholds.max_translation_m},
          {"max_rotation_deg", evaluation.thresholds.max_rotation_deg},
          {"min_gap_s", evaluation.thresholds.min_gap_s},
          {"images", evaluation.timestamps.size()},
          {"pairs", evaluation.pairs.size()},
          {"loop_pairs", evaluation.loop_pairs},
          {"mask_columns", evaluation.mask_columns},
          {"auc", "average precision (area under the step-interpolated PR curve)"},
          {"results", results}};
}

std::string loopTableMarkdown(const LoopEvaluation& evaluation,
                              const std::vector<std::string>& notes) {
  const auto& t = evaluation.thresholds;
  std::string text =
      fmt::format("## Loop detection: {}\n\n", evaluation.dataset.filename().string());
  text += fmt::format(
      "- {} database images (every {}th frame with a ground-truth pose); {} pairs at least {} s "
      "apart, {} of them loops (translation < {} m and rotation < {} deg): a random scorer's "
      "AUC is about {:.3f}\n",
      evaluation.timestamps.size(), evaluation.every, evaluation.pairs.size(), t.min_gap_s,
      evaluation.loop_pairs, t.max_translation_m, t.max_rotation_deg,
      static_cast<double>(evaluation.loop_pairs) / static_cast<double>(evaluation.pairs.size()));
  text += "- AUC = average precision (area under the step-interpolated precision-recall curve)\n";
  for (const auto& note : notes) text += "- " + note + "\n";
  text += "\n| method |";
  for (const auto& column : evaluation.mask_columns) text += " " + columnTitle(column) + " |";
  text += "\n| --- |";
  for (std::size_t c = 0; c < evaluation.mask_columns.size(); ++c) text += " ---: |";
  text += "\n";
  for (const auto& method : methodNames(evaluation)) {
    text += "| " + method + " |";
    for (const auto& column : evaluation.mask_columns) {
      std::string cell = " |";
      for (const auto& result : evaluation.results) {
        if (result.method == method && result.masks == column) {
          cell = " " + formatAp(result.curve.average_precision) + " |";
        }
      }
      text += cell;
    }
    text += "\n";
  }
  return text;
}

void writeLoopReport(const std::filesystem::path& out_dir, const LoopEvaluation& evaluation,
                     const std::vector<std::string>& notes) {
  std::filesystem::create_directories(out_dir);
  std::ofstream(out_dir / "loops.md") << loopTableMarkdown(evaluation, notes);
  nlohmann::json json = toJson(evaluation);
  json["notes"] = notes;
  std::ofstream(out_dir / "loops.json") << json.dump(2) << "\n";
  constexpr std::array<const char*, 12> kColours = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                                    "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
                                                    "#bcbd22", "#17becf", "#000000", "#aec7e8"};
  std::vector<std::string> bases;
  for (const auto& method : methodNames(evaluation)) {
    if (std::find(bases.begin(), bases.end(), baseMethodName(method)) == bases.end()) {
      bases.push_back(baseMethodName(method));
    }
  }
  std::vector<eval::Plot> plots;
  for (const auto& column : evaluation.mask_columns) {
    eval::Plot plot{fmt::format("Precision-recall, {}", columnTitle(column)), "recall",
                    "precision"};
    for (const auto& result : evaluation.results) {
      if (result.masks != column) continue;
      const auto colour_index =
          std::find(bases.begin(), bases.end(), baseMethodName(result.method)) - bases.begin();
      eval::PlotSeries series;
      series.label =
          fmt::format("{} ({})", result.method, formatAp(result.curve.average_precision));
      series.colour = kColours[static_cast<std::size_t>(colour_index) % kColours.size()];
      series.dash = dashOf(result.method);
      for (const auto& point : result.curve.points) {
        series.x.push_back(point.recall);
        series.y.push_back(point.precision);
      }
      plot.series.push_back(std::move(series));
    }
    plots.push_back(std::move(plot));
  }
  eval::writeSvg(out_dir / "pr_curves.svg", plots, {960.0, 420.0});
}

}  // namespace segslam::system
