#include "segslam/system/mask_evaluation.h"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "segslam/feature/orb_extractor.h"
#include "segslam/io/image_list.h"
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

// Predicted masks as a mask list: `timestamp masks/<timestamp>.png` per line, 255 = dynamic.
class MaskWriter {
 public:
  explicit MaskWriter(const std::filesystem::path& out_dir)
      : out_dir_(out_dir), list_(fmt::output_file((out_dir / "mask.txt").string())) {
    std::filesystem::create_directories(out_dir / "masks");
    list_.print("# predicted dynamic masks (255 = dynamic)\n");
  }

  void write(double timestamp, const cv::Mat& mask, const cv::Size& size) {
    const std::string name = fmt::format("masks/{:.6f}.png", timestamp);
    const cv::Mat image = mask.empty() ? cv::Mat::zeros(size, CV_8UC1) : mask;
    if (!cv::imwrite((out_dir_ / name).string(), image)) {
      util::failAt(out_dir_ / name, "cannot write the mask image");
    }
    list_.print("{:.6f} {}\n", timestamp, name);
  }

 private:
  std::filesystem::path out_dir_;
  fmt::ostream list_;
};

// Masks of pixels not to score, looked up by the frame's timestamp.
class IgnoredPixels {
 public:
  explicit IgnoredPixels(const std::filesystem::path& list)
      : list_(list), entries_(io::readImageList(list)) {
    if (entries_.empty()) util::failAt(list, "the ignore-mask list has no entries");
  }

  // The predicted mask with the ignored pixels cleared (those the ground truth marks excepted).
  cv::Mat apply(const cv::Mat& predicted, const cv::Mat& truth, double timestamp) const {
    if (predicted.empty()) return predicted;
    const cv::Mat ignored = load(timestamp, predicted.size());
    cv::Mat kept = predicted.clone();
    kept.setTo(0, (ignored != 0) & (truth == 0));
    return kept;
  }

 private:
  static constexpr double kMaxTimeDifference = 0.02;

  cv::Mat load(double timestamp, const cv::Size& size) const {
    const auto nearest = std::min_element(
        entries_.begin(), entries_.end(), [timestamp](const auto& a, const auto& b) {
          return std::abs(a.timestamp - timestamp) < std::abs(b.timestamp - timestamp);
        });
    if (std::abs(nearest->timestamp - timestamp) > kMaxTimeDifference) {
      util::failAt(list_, fmt::format("no ignore mask for the frame at {:.6f}", timestamp));
    }
    const auto file = list_.parent_path() / nearest->path;
    const cv::Mat image = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
    if (image.empty()) util::failAt(list_, nearest->line, "cannot read " + file.string());
    if (image.size() != size) {
      util::failAt(list_, nearest->line, file.string() + " does not have the frame's size");
    }
    return image;
  }

  std::filesystem::path list_;
  std::vector<io::ImageListEntry> entries_;
};

}  // namespace

MaskEvaluationSummary summariseMaskScores(std::vector<FrameMaskScores> frames) {
  MaskEvaluationSummary summary;
  summary.frames = std::move(frames);
  for (const auto& frame : summary.frames) {
    summary.total += frame.scores;
    summary.survival += frame.survival;
    if (!frame.truth_dynamic) continue;
    summary.total_where_dynamic += frame.scores;
    ++summary.frames_with_dynamic;
    summary.mean_iou += frame.scores.iou();
    summary.mean_precision += frame.scores.precision();
    summary.mean_recall += frame.scores.recall();
  }
  if (summary.frames_with_dynamic == 0) return summary;
  const auto n = static_cast<double>(summary.frames_with_dynamic);
  summary.mean_iou /= n;
  summary.mean_precision /= n;
  summary.mean_recall /= n;
  return summary;
}

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
  std::filesystem::create_directories(out_dir);
  std::optional<MaskWriter> mask_writer;
  if (options.write_masks) mask_writer.emplace(out_dir);
  std::optional<IgnoredPixels> ignored;
  if (options.ignore_masks) ignored.emplace(*options.ignore_masks);
  std::vector<FrameMaskScores> scored_frames;
  const std::size_t frames = std::min(options.max_frames, dataset.size());
  for (std::size_t i = 0; i < frames; ++i) {
    const io::RgbdFrame frame = dataset.loadFrame(i);
    const cv::Mat predicted = source.dynamicMask(frame, i);
    FrameMaskScores scores;
    scores.timestamp = frame.timestamp;
    scores.truth_dynamic = cv::countNonZero(frame.mask) > 0;
    const cv::Mat scored =
        ignored ? ignored->apply(predicted, frame.mask, frame.timestamp) : predicted;
    scores.scores = eval::compareMasks(scored, frame.mask);
    scores.survival = keypointSurvival(extractor, frame.rgb, predicted, frame.mask);
    scored_frames.push_back(scores);
    if (mask_writer) mask_writer->write(frame.timestamp, predicted, frame.mask.size());
    if (on_frame) on_frame();
  }
  const MaskEvaluationSummary summary = summariseMaskScores(std::move(scored_frames));
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
          {"pixel_iou_where_dynamic", summary.total_where_dynamic.iou()},
          {"pixel_precision_where_dynamic", summary.total_where_dynamic.precision()},
          {"pixel_recall_where_dynamic", summary.total_where_dynamic.recall()},
          {"keypoints_on_dynamic_unmasked", summary.survival.on_dynamic_without_mask},
          {"keypoints_on_dynamic_masked", summary.survival.on_dynamic_with_mask},
          {"keypoint_survival", summary.survival.survivingShare()}};
}

}  // namespace segslam::system
