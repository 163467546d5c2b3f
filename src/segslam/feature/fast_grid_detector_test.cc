#include "segslam/feature/fast_grid_detector.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "segslam/feature/feature_test_images.h"

namespace segslam::feature {
namespace {

int countInColumns(const std::vector<cv::KeyPoint>& corners, float x_begin, float x_end) {
  int count = 0;
  for (const auto& corner : corners) count += corner.pt.x >= x_begin && corner.pt.x < x_end;
  return count;
}

TEST(FeatureFastGrid, FallsBackToTheLowThresholdInLowContrastCells) {
  // Strong texture on the left, faint texture (contrast about 16) on the right.
  cv::Mat image = testing::texturedImage({320, 240}, 11);
  testing::texturedImage({160, 240}, 12, 450, 16).copyTo(image(cv::Rect(160, 0, 160, 240)));
  FastGridOptions options;
  const auto corners = detectFastInGrid(image, LevelToBase{}, StaticMask(), options);
  EXPECT_GT(countInColumns(corners, 0, 150), 50);
  EXPECT_GT(countInColumns(corners, 170, 320), 20);

  options.min_threshold = options.initial_threshold;  // no fallback: the faint side stays empty
  const auto strong_only = detectFastInGrid(image, LevelToBase{}, StaticMask(), options);
  EXPECT_LT(countInColumns(strong_only, 170, 320), 5);
}

TEST(FeatureFastGrid, KeepsBorderAndMaskAtLevelScale) {
  const cv::Mat image = testing::texturedImage({200, 150}, 5);
  cv::Mat dynamic(300, 400, CV_8UC1, cv::Scalar(0));  // level 0 is twice the size
  dynamic(cv::Rect(0, 0, 200, 300)).setTo(255);
  const StaticMask mask(dynamic, 10);
  FastGridOptions options;
  const LevelToBase to_base{2.0f, 2.0f};
  const auto corners = detectFastInGrid(image, to_base, mask, options);
  ASSERT_FALSE(corners.empty());
  for (const auto& corner : corners) {
    const cv::Point2f base = to_base(corner.pt);
    EXPECT_GT(base.x, 209.0f);  // more than 10 px right of the masked half
    EXPECT_TRUE(mask.isStatic(cv::Point(cvRound(base.x), cvRound(base.y))));
    EXPECT_GE(corner.pt.y, options.border);
    EXPECT_LT(corner.pt.x, image.cols - options.border);
    EXPECT_GT(corner.response, 0.0f);
  }
  EXPECT_TRUE(detectFastInGrid(cv::Mat(20, 20, CV_8UC1, cv::Scalar(0)), LevelToBase{}, StaticMask(),
                               options)
                  .empty());
}

}  // namespace
}  // namespace segslam::feature
