#include "segslam/eval/mask_metrics.h"

#include <stdexcept>

namespace segslam::eval {

namespace {

double ratio(std::int64_t numerator, std::int64_t denominator) {
  return denominator == 0 ? 1.0 : static_cast<double>(numerator) / static_cast<double>(denominator);
}

}  // namespace

double MaskScores::iou() const {
  return ratio(true_positive, true_positive + false_positive + false_negative);
}

double MaskScores::precision() const {
  return ratio(true_positive, true_positive + false_positive);
}

double MaskScores::recall() const { return ratio(true_positive, true_positive + false_negative); }

MaskScores& MaskScores::operator+=(const MaskScores& other) {
  true_positive += other.true_positive;
  false_positive += other.false_positive;
  false_negative += other.false_negative;
  return *this;
}

MaskScores compareMasks(const cv::Mat& predicted, const cv::Mat& truth) {
  if (truth.type() != CV_8UC1 ||
      (!predicted.empty() && (predicted.type() != CV_8UC1 || predicted.size() != truth.size()))) {
    throw std::invalid_argument("compareMasks: CV_8UC1 masks of the same size expected");
  }
  const cv::Mat truly = truth != 0;
  MaskScores scores;
  if (predicted.empty()) {
    scores.false_negative = cv::countNonZero(truly);
    return scores;
  }
  const cv::Mat predicted_dynamic = predicted != 0;
  scores.true_positive = cv::countNonZero(predicted_dynamic & truly);
  scores.false_positive = cv::countNonZero(predicted_dynamic & ~truly);
  scores.false_negative = cv::countNonZero(~predicted_dynamic & truly);
  return scores;
}

double KeypointSurvival::survivingShare() const {
  if (on_dynamic_without_mask == 0) return 0.0;
  return ratio(on_dynamic_with_mask, on_dynamic_without_mask);
}

KeypointSurvival& KeypointSurvival::operator+=(const KeypointSurvival& other) {
  on_dynamic_without_mask += other.on_dynamic_without_mask;
  on_dynamic_with_mask += other.on_dynamic_with_mask;
  return *this;
}

std::int64_t keypointsOnDynamic(const std::vector<cv::KeyPoint>& keypoints, const cv::Mat& truth) {
  std::int64_t count = 0;
  for (const auto& keypoint : keypoints) {
    const int x = cvRound(keypoint.pt.x);
    const int y = cvRound(keypoint.pt.y);
    if (x >= 0 && y >= 0 && x < truth.cols && y < truth.rows && truth.at<std::uint8_t>(y, x) != 0) {
      ++count;
    }
  }
  return count;
}

}  // namespace segslam::eval
