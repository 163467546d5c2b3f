#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segslam/feature/scale_levels.h"

namespace segslam::feature {

// Size of the pyramid level at `scale` (factor^level) for an image of `size`: divided and rounded.
cv::Size pyramidLevelSize(cv::Size size, double scale);

// Maps pixel coordinates of a pyramid level to level 0. cv::resize aligns pixel centres,
// (x_level + 0.5) = (x_0 + 0.5) * level_width / width, and rounded level sizes make the true
// factor differ slightly from factor^level; `x * scale` alone would shift the keypoints of the
// top level by more than a pixel towards the image origin.
struct LevelToBase {
  float x_factor = 1.0f;  // base width / level width
  float y_factor = 1.0f;

  static LevelToBase between(cv::Size base, cv::Size level);
  [[nodiscard]] cv::Point2f operator()(const cv::Point2f& level_point) const {
    return {(level_point.x + 0.5f) * x_factor - 0.5f, (level_point.y + 0.5f) * y_factor - 0.5f};
  }
};

// Fills `levels` with the pyramid of `gray` (level 0 shares gray's data). Each level is resized
// bilinearly from the one before, which is cheaper than from level 0 and, at factor 1.2, barely
// different. `levels` is reused between calls to avoid reallocating the images every frame.
void buildImagePyramid(const cv::Mat& gray, const ScaleLevels& scale_levels,
                       std::vector<cv::Mat>& levels);

}  // namespace segslam::feature
