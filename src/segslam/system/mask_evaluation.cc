#include "segslam/system/mask_evaluation.h"

#include <fmt/os.h>

#include <fstream>
#include <opencv2/imgproc.hpp>

#include "segslam/feature/orb_extractor.h"
#include "segslam/util/error.h"

namespace segslam::system {

namespace {

eval::KeypointSurvival keypointSurvival(feature::OrbExtractor& extractor, const cv::Mat& bgr,
                                        const cv::Mat& predicted, const cv::Mat& truth) {
  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  std::vector<cv::KeyPoint> unmasked;
  std::vector<cv::KeyPoint> masked;
  cv::Mat descriptors;
  extractor.extract(gray, cv::Mat(), unmasked, descriptors);
  extractor.extract(gray, predicted, masked, descriptors);
  return {eval::keypointsOnDynamic(unmasked, truth), eval::keypointsOnDynamic(masked, truth)};
}

void summarise(MaskEvaluationSummary& summary) {
  for (const auto& frame : summary.frames) {
    summary.total += frame.scores;
    summary.survival += frame.survival;
    if (!frame.truth_dynamic) continue;
    ++summary.frames_with_dynamic;
    summary.mean_iou += frame.scores.iou();
    summary.mean_precision += frame.scores.precision();
    summary.mean_recall += frame.scores.recall();
  }
  if (summary.frames_with_dynamic == 0) return;
  const auto n = static_cast<double>(summary.frames_with_dynamic);
  summary.mean_iou /= n;
  summary.mean_precision /= n;
  summary.mean_recall /= n;
}

void writeCsv(const std::filesystem::path& file, const MaskEvaluationSummary& summary) {
  auto out = fmt::output_file(file.string());
  out.print(
      "timestamp,truth_dynamic,iou,precision,recall,keypoints_on_dynamic_unmasked,"
      "keypoints_on_dynamic_masked\n");
  for (const auto& f : summary.frames) {
    out.print("{:.6f},{},{:.4f},{:.4f},{:.4f},{},{}\n", f.timestamp, f.truth_dynamic ? 1 : 0,
              f.scores.iou(), f.scores.precision(), f.scores.recall(),
              f.survival.on_dynamic_without_mask, f.survival.on_dynamic_with_mask);
  }
}

}  // namespace

MaskEvaluationSummary evaluateMasks(const io::TumDataset& dataset,
                                    const MaskEvaluationOptions& options,
                                    const std::filesystem::path& out_dir,
                                    const std::function<void()>& on_frame) {
  if (!dataset.hasMasks()) {
    util::failAt(dataset.folder() / "mask.txt",
                 "mask evaluation needs ground-truth masks, and the dataset has no mask.txt");
  }
  FrameMaskSource source(dataset, options.masks, options.synchronous);
  feature::OrbExtractorOptions extractor_options;
  extractor_options.num_features = options.features;
  extractor_options.mask_dilation_px = options.mask_dilation_px;
  feature::OrbExtractor extractor(extractor_options);
  MaskEvaluationSummary summary;
  const std::size_t frames = std::min(options.max_frames, dataset.size());
  for (std::size_t i = 0; i < frames; ++i) {
    const io::RgbdFrame frame = dataset.loadFrame(i);
    const cv::Mat predicted = source.dynamicMask(frame, i);
    FrameMaskScores scores;
    scores.timestamp = frame.timestamp;
    scores.truth_dynamic = cv::countNonZero(frame.mask) > 0;
    scores.scores = eval::compareMasks(predicted, frame.mask);
    scores.survival = keypointSurvival(extractor, frame.rgb, predicted, frame.mask);
    summary.frames.push_back(scores);
    if (on_frame) on_frame();
  }
  summarise(summary);
  std::filesystem::create_directories(out_dir);
  writeCsv(out_dir / "mask_evaluation.csv", summary);
  std::ofstream(out_dir / "mask_evaluation.json") << toJson(summary).dump(2) << "\n";
  return summary;
}

nlohmann::json toJson(const MaskEvaluationSummary& summary) {
  return {{"frames", summary.frames.size()},
          {"frames_with_dynamic", summary.frames_with_dynamic},
          {"mean_iou", summary.mean_iou},
          {"mean_precision", summary.mean_precision},
          {"mean_recall", summary.mean_recall},
          {"pixel_iou", summary.total.iou()},
          {"pixel_precision", summary.total.precision()},
          {"pixel_recall", summary.total.recall()},
          {"keypoints_on_dynamic_unmasked", summary.survival.on_dynamic_without_mask},
          {"keypoints_on_dynamic_masked", summary.survival.on_dynamic_with_mask},
          {"keypoint_survival", summary.survival.survivingShare()}};
}

}  // namespace segslam::system
