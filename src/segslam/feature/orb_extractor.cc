#include "segslam/feature/orb_extractor.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "segslam/feature/descriptor_distance.h"
#include "segslam/feature/fast_grid_detector.h"
#include "segslam/feature/image_pyramid.h"
#include "segslam/feature/level_budget.h"
#include "segslam/feature/orb_descriptor.h"
#include "segslam/feature/orb_orientation.h"
#include "segslam/feature/orb_pattern.h"
#include "segslam/feature/quadtree_distribution.h"
#include "segslam/feature/static_mask.h"

namespace segslam::feature {
namespace {

// Keypoint centres stay this far from a level's border: the orientation disc and the steered
// test points (rounded, within kPatternRadius) then lie inside the image.
constexpr int kBorder = std::max(kOrientationRadius, kPatternRadius);
// Diameter of the patch a keypoint is described by, reported as cv::KeyPoint::size at level 0.
constexpr float kPatchDiameter = 2.0f * kPatternRadius + 1.0f;

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("OrbExtractor: " + message);
}

void validateOptions(const OrbExtractorOptions& options) {
  require(options.num_features >= 0, "num_features must be >= 0");
  require(options.initial_fast_threshold >= 1 && options.initial_fast_threshold <= 255,
          "initial_fast_threshold must be in [1, 255]");
  require(options.min_fast_threshold >= 1 &&
              options.min_fast_threshold <= options.initial_fast_threshold,
          "min_fast_threshold must be in [1, initial_fast_threshold]");
  require(options.cell_size >= 8, "cell_size must be at least 8 pixels");
  require(options.mask_dilation_px >= 0, "mask_dilation_px must be >= 0");
}

void validateInput(const cv::Mat& gray, const cv::Mat& dynamic_mask) {
  require(!gray.empty(), "empty image");
  require(gray.type() == CV_8UC1,
          "image must be 8-bit single-channel (CV_8UC1), got type " + std::to_string(gray.type()));
  if (dynamic_mask.empty()) return;
  require(dynamic_mask.type() == CV_8UC1,
          "dynamic mask must be CV_8UC1, got type " + std::to_string(dynamic_mask.type()));
  require(dynamic_mask.size() == gray.size(),
          "dynamic mask is " + std::to_string(dynamic_mask.cols) + "x" +
              std::to_string(dynamic_mask.rows) + " but the image is " + std::to_string(gray.cols) +
              "x" + std::to_string(gray.rows));
}

FastGridOptions fastGridOptions(const OrbExtractorOptions& options) {
  FastGridOptions grid;
  grid.cell_size = options.cell_size;
  grid.initial_threshold = options.initial_fast_threshold;
  grid.min_threshold = options.min_fast_threshold;
  grid.border = kBorder;
  return grid;
}

// The levels' descriptor rows as one fresh N x 32 matrix. Fresh, never cv::Mat::create on the
// caller's matrix: that would write into the buffer of the previous frame's descriptors whenever
// the caller still shares it and the row count happens to match.
cv::Mat stackRows(const std::vector<cv::Mat>& blocks, int rows) {
  cv::Mat stacked(rows, kDescriptorBytes, CV_8UC1);
  int row = 0;
  for (const cv::Mat& block : blocks) {
    if (block.rows == 0) continue;
    block.copyTo(stacked.rowRange(row, row + block.rows));
    row += block.rows;
  }
  return stacked;
}

}  // namespace

OrbExtractor::OrbExtractor(const OrbExtractorOptions& options)
    : options_(options),
      scale_levels_(options.num_levels, options.scale_factor),
      brief_(learnedOrbPattern()) {
  validateOptions(options_);
  level_shares_ = levelFeatureShares(options_.num_features, scale_levels_);
}

void OrbExtractor::extract(const cv::Mat& gray, const cv::Mat& dynamic_mask,
                           std::vector<cv::KeyPoint>& keypoints, cv::Mat& descriptors) {
  run(gray, dynamic_mask, keypoints, &descriptors);
}

void OrbExtractor::detect(const cv::Mat& gray, const cv::Mat& dynamic_mask,
                          std::vector<cv::KeyPoint>& keypoints) {
  run(gray, dynamic_mask, keypoints, nullptr);
}

template <typename LevelWork>
void OrbExtractor::forEachLevel(const LevelWork& work) const {
  if (options_.parallel_levels) {
    tbb::parallel_for(0, numLevels(), [&](int level) { work(level); });
  } else {
    for (int level = 0; level < numLevels(); ++level) work(level);
  }
}

void OrbExtractor::run(const cv::Mat& gray, const cv::Mat& dynamic_mask,
                       std::vector<cv::KeyPoint>& keypoints, cv::Mat* descriptors) {
  validateInput(gray, dynamic_mask);
  static_mask_.assign(dynamic_mask, options_.mask_dilation_px);
  buildImagePyramid(gray, scale_levels_, pyramid_);
  const FastGridOptions grid = fastGridOptions(options_);
  std::vector<std::vector<cv::KeyPoint>> level_keypoints(numLevels());
  forEachLevel([&](int level) {
    level_keypoints[level] = detectFastInGrid(
        pyramid_[level], LevelToBase::between(pyramid_[0].size(), pyramid_[level].size()),
        static_mask_, grid);
  });

  std::vector<int> capacities;
  for (const auto& candidates : level_keypoints) {
    capacities.push_back(static_cast<int>(candidates.size()));
  }
  const std::vector<int> budgets = allocateLevelBudgets(level_shares_, capacities);

  smoothed_.resize(numLevels());
  std::vector<cv::Mat> level_descriptors(numLevels());
  forEachLevel([&](int level) {
    const cv::Rect2f area(detectionRegion(pyramid_[level].size(), kBorder));
    level_keypoints[level] = distributeWithQuadtree(level_keypoints[level], area, budgets[level]);
    orientAndDescribe(level, level_keypoints[level],
                      descriptors ? &level_descriptors[level] : nullptr);
  });

  keypoints.clear();
  for (const auto& level : level_keypoints) {
    keypoints.insert(keypoints.end(), level.begin(), level.end());
  }
  if (descriptors) *descriptors = stackRows(level_descriptors, static_cast<int>(keypoints.size()));
}

void OrbExtractor::orientAndDescribe(int level, std::vector<cv::KeyPoint>& level_keypoints,
                                     cv::Mat* descriptors) {
  const cv::Mat& image = pyramid_[level];
  if (descriptors) {
    smoothForDescriptor(image, smoothed_[level]);
    *descriptors = cv::Mat(static_cast<int>(level_keypoints.size()), kDescriptorBytes, CV_8UC1);
  }
  const auto scale = static_cast<float>(scaleFactors()[level]);
  const LevelToBase to_base = LevelToBase::between(pyramid_[0].size(), image.size());
  for (std::size_t i = 0; i < level_keypoints.size(); ++i) {
    cv::KeyPoint& keypoint = level_keypoints[i];
    const cv::Point center(cvRound(keypoint.pt.x), cvRound(keypoint.pt.y));
    keypoint.angle = intensityCentroidAngle(image, center);
    if (descriptors) {
      brief_.compute(smoothed_[level], center, keypoint.angle,
                     descriptors->ptr<std::uint8_t>(static_cast<int>(i)));
    }
    keypoint.pt = to_base(keypoint.pt);
    keypoint.octave = level;
    keypoint.size = kPatchDiameter * scale;
  }
}

}  // namespace segslam::feature
