#include "segslam/eval/mask_metrics.h"

#include <gtest/gtest.h>

namespace segslam::eval {
namespace {

TEST(MaskMetrics, CountsAgreementPixelByPixel) {
  cv::Mat truth(10, 10, CV_8UC1, cv::Scalar(0));
  cv::Mat predicted(10, 10, CV_8UC1, cv::Scalar(0));
  truth(cv::Rect(0, 0, 4, 5)).setTo(255);    // 20 pixels
  predicted(cv::Rect(2, 0, 4, 5)).setTo(1);  // 20 pixels, 10 of them shared
  const MaskScores scores = compareMasks(predicted, truth);
  EXPECT_EQ(scores.true_positive, 10);
  EXPECT_EQ(scores.false_positive, 10);
  EXPECT_EQ(scores.false_negative, 10);
  EXPECT_DOUBLE_EQ(scores.iou(), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(scores.precision(), 0.5);
  EXPECT_DOUBLE_EQ(scores.recall(), 0.5);
}

TEST(MaskMetrics, EmptyMasksAreHandled) {
  const cv::Mat nothing(4, 4, CV_8UC1, cv::Scalar(0));
  EXPECT_DOUBLE_EQ(compareMasks(nothing, nothing).iou(), 1.0);
  const cv::Mat everything(4, 4, CV_8UC1, cv::Scalar(255));
  const MaskScores missed = compareMasks(cv::Mat(), everything);
  EXPECT_EQ(missed.false_negative, 16);
  EXPECT_DOUBLE_EQ(missed.recall(), 0.0);
  EXPECT_DOUBLE_EQ(missed.precision(), 1.0);
  EXPECT_THROW(compareMasks(cv::Mat(3, 3, CV_8UC1), everything), std::invalid_argument);
}

TEST(MaskMetrics, KeypointSurvivalIsTheShareLeftOnMovingObjects) {
  cv::Mat truth(10, 10, CV_8UC1, cv::Scalar(0));
  truth(cv::Rect(0, 0, 5, 10)).setTo(255);
  const std::vector<cv::KeyPoint> keypoints = {
      {1.2f, 3.0f, 1.0f}, {4.4f, 9.0f, 1.0f}, {7.0f, 2.0f, 1.0f}, {-3.0f, 2.0f, 1.0f}};
  EXPECT_EQ(keypointsOnDynamic(keypoints, truth), 2);
  KeypointSurvival survival{4, 1};
  survival += KeypointSurvival{4, 0};
  EXPECT_DOUBLE_EQ(survival.survivingShare(), 1.0 / 8.0);
  EXPECT_DOUBLE_EQ(KeypointSurvival{}.survivingShare(), 0.0);
}

}  // namespace
}  // namespace segslam::eval
