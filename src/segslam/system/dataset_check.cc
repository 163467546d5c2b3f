#include "segslam/system/dataset_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <optional>

#include "segslam/io/damaged_frames.h"
#include "segslam/io/frame_images.h"
#include "segslam/io/timestamp_association.h"

namespace segslam::system {

namespace {

struct DepthStats {
  double valid_share = 0.0;
  double min_m = std::numeric_limits<double>::infinity();
  double max_m = 0.0;
};

DepthStats depthStats(const cv::Mat& depth) {
  const cv::Mat valid = depth > 0.0f;
  DepthStats stats;
  const int valid_count = cv::countNonZero(valid);
  stats.valid_share = static_cast<double>(valid_count) / static_cast<double>(depth.total());
  if (valid_count > 0) cv::minMaxLoc(depth, &stats.min_m, &stats.max_m, nullptr, nullptr, valid);
  return stats;
}

std::size_t framesWithGroundTruth(const io::TumDataset& dataset, std::size_t frame_count,
                                  double max_difference) {
  if (!dataset.groundTruth()) return 0;
  std::vector<double> stamps;
  for (std::size_t i = 0; i < frame_count; ++i) stamps.push_back(dataset.frames()[i].timestamp);
  return io::associateTimestamps(stamps, dataset.groundTruth()->timestamps(), max_difference)
      .size();
}

// The frame, or nothing when an image of it is damaged (warned and counted by `damaged`).
std::optional<io::RgbdFrame> loadUndamaged(const io::TumDataset& dataset, std::size_t i,
                                           io::DamagedFrames& damaged) {
  try {
    return dataset.loadFrame(i);
  } catch (const io::DamagedImageError& e) {
    damaged.skip(i, dataset.frames()[i].timestamp, e.what());
    return std::nullopt;
  }
}

}  // namespace

DatasetCheck checkDataset(const io::TumDataset& dataset, std::size_t max_frames,
                          const std::function<void()>& on_frame) {
  DatasetCheck check;
  check.frames = std::min(dataset.size(), max_frames);
  const auto& records = dataset.frames();
  io::DamagedFrames damaged(dataset.folder(), check.frames);
  double valid_share_sum = 0.0;
  double dynamic_share_sum = 0.0;
  check.min_depth_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < check.frames; ++i) {
    if (const auto frame = loadUndamaged(dataset, i, damaged)) {
      const DepthStats depth = depthStats(frame->depth);
      valid_share_sum += depth.valid_share;
      check.min_depth_m = std::min(check.min_depth_m, depth.min_m);
      check.max_depth_m = std::max(check.max_depth_m, depth.max_m);
      check.max_rgb_depth_gap_s = std::max(
          check.max_rgb_depth_gap_s, std::abs(records[i].timestamp - records[i].depth_timestamp));
      if (!frame->mask.empty()) {
        const int dynamic = cv::countNonZero(frame->mask);
        dynamic_share_sum +=
            static_cast<double>(dynamic) / static_cast<double>(frame->mask.total());
        if (dynamic > 0) ++check.frames_with_dynamic_pixels;
      }
    }
    if (on_frame) on_frame();
  }
  check.skipped_frames = damaged.count();
  const std::size_t loaded = check.frames - check.skipped_frames;
  if (check.frames > 0) {
    check.duration_s = records[check.frames - 1].timestamp - records[0].timestamp;
    check.mean_frame_rate = check.duration_s > 0.0 ? (check.frames - 1) / check.duration_s : 0.0;
  }
  if (loaded > 0) {
    check.valid_depth_share = valid_share_sum / static_cast<double>(loaded);
    check.mean_dynamic_share = dynamic_share_sum / static_cast<double>(loaded);
  }
  if (!std::isfinite(check.min_depth_m)) check.min_depth_m = 0.0;
  check.absent_images = dataset.absentImages();
  check.ground_truth_frame = dataset.groundTruthFrame();
  if (dataset.groundTruth()) check.ground_truth_poses = dataset.groundTruth()->size();
  check.frames_with_ground_truth = framesWithGroundTruth(dataset, check.frames, 0.02);
  return check;
}

nlohmann::json toJson(const DatasetCheck& check) {
  nlohmann::json absent = nlohmann::json::array();
  for (const auto& image : check.absent_images) {
    absent.push_back(
        {{"list", image.list_file.string()}, {"line", image.line}, {"path", image.path.string()}});
  }
  return {{"frames", check.frames},
          {"absent_images", absent},
          {"skipped_frames", check.skipped_frames},
          {"duration_s", check.duration_s},
          {"mean_frame_rate", check.mean_frame_rate},
          {"max_rgb_depth_gap_s", check.max_rgb_depth_gap_s},
          {"valid_depth_share", check.valid_depth_share},
          {"min_depth_m", check.min_depth_m},
          {"max_depth_m", check.max_depth_m},
          {"frames_with_dynamic_pixels", check.frames_with_dynamic_pixels},
          {"mean_dynamic_share", check.mean_dynamic_share},
          {"ground_truth_frame", io::groundTruthFrameName(check.ground_truth_frame)},
          {"ground_truth_poses_of", io::describeGroundTruthFrame(check.ground_truth_frame)},
          {"ground_truth_poses", check.ground_truth_poses},
          {"frames_with_ground_truth", check.frames_with_ground_truth}};
}

}  // namespace segslam::system
