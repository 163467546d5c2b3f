#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segslam/feature/image_pyramid.h"
#include "segslam/feature/static_mask.h"

namespace segslam::feature {

struct FastGridOptions {
  // Side of the square-ish cells FAST runs in, in level pixels.
  int cell_size = 30;
  // FAST threshold tried first in every cell, and the lower one tried when a cell yields nothing:
  // low-contrast regions still get corners, high-contrast ones are not flooded with weak ones.
  int initial_threshold = 20;
  int min_threshold = 7;
  // Keypoints keep this distance from the level border so that their orientation and descriptor
  // patches lie inside the image.
  int border = 16;
};

// The part of a level where keypoint centres may lie: the level minus `border` on every side.
// Empty when the level is too small.
cv::Rect detectionRegion(cv::Size level_size, int border);

// FAST-9 corners of one pyramid level, found cell by cell with the fallback threshold, in level
// coordinates with the FAST score as response. `to_base` maps level to level-0 pixels, where
// `static_mask` is asked: only corners whose level-0 position (rounded by cvRound) is static
// are kept, and cells that are wholly dynamic are not searched. Corners come in cell order
// (row-major), so the output is deterministic.
std::vector<cv::KeyPoint> detectFastInGrid(const cv::Mat& level_image, const LevelToBase& to_base,
                                           const StaticMask& static_mask,
                                           const FastGridOptions& options);

}  // namespace segslam::feature
