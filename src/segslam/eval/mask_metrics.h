#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

// Agreement of a predicted dynamic mask with the ground-truth one (non-zero = dynamic).
namespace segslam::eval {

struct MaskScores {
  std::int64_t true_positive = 0;   // dynamic in both
  std::int64_t false_positive = 0;  // predicted dynamic, truly static
  std::int64_t false_negative = 0;  // truly dynamic, predicted static

  // 1 when both masks are empty (nothing to find, nothing found).
  [[nodiscard]] double iou() const;
  [[nodiscard]] double precision() const;  // 1 when nothing is predicted
  [[nodiscard]] double recall() const;     // 1 when nothing is truly dynamic
  MaskScores& operator+=(const MaskScores& other);
};

// Both CV_8UC1 of the same size; an empty predicted mask means nothing predicted.
MaskScores compareMasks(const cv::Mat& predicted, const cv::Mat& truth);

// Keypoints that lie on ground-truth dynamic pixels, with and without the predicted mask.
struct KeypointSurvival {
  std::int64_t on_dynamic_without_mask = 0;  // extracted with no mask at all
  std::int64_t on_dynamic_with_mask = 0;     // extracted with the predicted (dilated) mask

  // Share of the keypoints on moving objects that the predicted mask fails to remove (0 when
  // there were none).
  [[nodiscard]] double survivingShare() const;
  KeypointSurvival& operator+=(const KeypointSurvival& other);
};

// Keypoints (level-0 coordinates) whose rounded position is dynamic in `truth`.
std::int64_t keypointsOnDynamic(const std::vector<cv::KeyPoint>& keypoints, const cv::Mat& truth);

}  // namespace segslam::eval
