#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segslam/feature/scale_levels.h"

namespace segslam::feature {

// Size of the pyramid level at `scale` (factor^level) for an image of `size`: divided and rounded.
cv::Size pyramidLevelSize(cv::Size size, double scale);

// Fills `levels` with the pyramid of `gray` (level 0 shares gray's data). Each level is resized
// bilinearly from the one before, which is cheaper than from level 0 and, at factor 1.2, barely
// different. `levels` is reused between calls to avoid reallocating the images every frame.
void buildImagePyramid(const cv::Mat& gray, const ScaleLevels& scale_levels,
                       std::vector<cv::Mat>& levels);

}  // namespace segslam::feature
