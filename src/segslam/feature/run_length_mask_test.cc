#include "segslam/feature/run_length_mask.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "segslam/feature/static_mask.h"

namespace segslam::feature {
namespace {

cv::Mat personLikeMask() {
  cv::Mat mask = cv::Mat::zeros(48, 64, CV_8UC1);
  cv::ellipse(mask, {20, 24}, {8, 20}, 0.0, 0.0, 360.0, cv::Scalar(255), cv::FILLED);
  cv::circle(mask, {50, 10}, 5, cv::Scalar(7), cv::FILLED);  // any non-zero value is set
  mask.col(63).setTo(1);                                     // runs reaching the last column
  mask.at<std::uint8_t>(0, 0) = 200;
  return mask;
}

TEST(RunLengthMask, AnswersAsTheImageDoesAtEveryPixelAndBetween) {
  const cv::Mat mask = personLikeMask();
  const RunLengthMask runs(mask);
  ASSERT_FALSE(runs.empty());
  EXPECT_EQ(runs.size(), mask.size());
  int mismatches = 0;
  for (float y = -2.0f; y < 50.0f; y += 0.25f) {
    for (float x = -2.0f; x < 66.0f; x += 0.25f) {
      mismatches += runs.at({x, y}) != isDynamicAt(mask, {x, y});
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(cv::countNonZero(runs.toMat() != (mask != 0)), 0);
}

TEST(RunLengthMask, NothingSetIsEmpty) {
  EXPECT_TRUE(RunLengthMask().empty());
  EXPECT_TRUE(RunLengthMask(cv::Mat()).empty());
  const RunLengthMask zeros(cv::Mat::zeros(10, 10, CV_8UC1));
  EXPECT_TRUE(zeros.empty());
  EXPECT_FALSE(zeros.at({5.0f, 5.0f}));
  EXPECT_TRUE(zeros.toMat().empty());
}

TEST(RunLengthMask, UnitesWithAnImage) {
  cv::Mat left = cv::Mat::zeros(20, 30, CV_8UC1);
  left.colRange(0, 10).setTo(255);
  cv::Mat right = cv::Mat::zeros(20, 30, CV_8UC1);
  right.colRange(20, 30).setTo(255);
  const RunLengthMask both = RunLengthMask(left).united(right);
  EXPECT_EQ(cv::countNonZero(both.toMat() != (left | right)), 0);
  EXPECT_EQ(cv::countNonZero(RunLengthMask().united(right).toMat() != right), 0);
  EXPECT_EQ(cv::countNonZero(RunLengthMask(left).united(cv::Mat()).toMat() != left), 0);
  EXPECT_THROW(RunLengthMask(left).united(cv::Mat::zeros(10, 10, CV_8UC1)), std::invalid_argument);
}

TEST(RunLengthMask, RejectsImagesOfOtherTypes) {
  EXPECT_THROW(RunLengthMask(cv::Mat::zeros(10, 10, CV_16UC1)), std::invalid_argument);
  EXPECT_THROW(RunLengthMask(cv::Mat::zeros(10, 10, CV_8UC3)), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::feature
