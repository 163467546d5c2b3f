#include "segslam/feature/static_mask.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

namespace segslam::feature {
namespace {

// The dilated dynamic area by definition: pixels within Euclidean distance `radius` of a dynamic
// pixel (exact distance transform).
cv::Mat dilatedByDistance(const cv::Mat& dynamic_mask, int radius) {
  cv::Mat static_pixels = dynamic_mask == 0;
  cv::Mat distance;
  cv::distanceTransform(static_pixels, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance <= radius;
}

TEST(FeatureStaticMask, MatchesEuclideanDilationPixelForPixel) {
  cv::Mat dynamic(60, 80, CV_8UC1, cv::Scalar(0));
  cv::circle(dynamic, {30, 25}, 6, cv::Scalar(255), cv::FILLED);
  dynamic.at<std::uint8_t>(50, 70) = 1;  // any non-zero value is dynamic
  for (const int radius : {0, 3, 10}) {
    const StaticMask mask(dynamic, radius);
    const cv::Mat expected = dilatedByDistance(dynamic, radius);
    int mismatches = 0;
    for (int y = 0; y < dynamic.rows; ++y) {
      for (int x = 0; x < dynamic.cols; ++x) {
        mismatches += mask.isStatic({x, y}) == (expected.at<std::uint8_t>(y, x) != 0);
      }
    }
    EXPECT_EQ(mismatches, 0) << "radius " << radius;
  }
}

TEST(FeatureStaticMask, RectangleQueries) {
  cv::Mat dynamic(100, 100, CV_8UC1, cv::Scalar(0));
  dynamic(cv::Rect(40, 40, 20, 20)).setTo(255);
  const StaticMask mask(dynamic, 5);
  EXPECT_FALSE(mask.everythingStatic());
  EXPECT_TRUE(mask.isDynamicRect({45, 45, 10, 10}));
  EXPECT_FALSE(mask.isDynamicRect({35, 45, 10, 10}));
  EXPECT_TRUE(mask.isStaticRect({0, 0, 30, 30}));
  EXPECT_FALSE(mask.isStaticRect({0, 0, 36, 36}));     // within 5 px of the square
  EXPECT_TRUE(mask.isStaticRect({-10, -10, 20, 20}));  // partly outside the image

  const StaticMask everything_static;
  EXPECT_TRUE(everything_static.everythingStatic());
  EXPECT_TRUE(everything_static.isStatic({5, 5}));
  EXPECT_FALSE(everything_static.isDynamicRect({0, 0, 5, 5}));
  EXPECT_TRUE(StaticMask(cv::Mat(), 10).everythingStatic());
}

TEST(FeatureStaticMask, DilationAroundTheObjectsEqualsDilatingTheWholeFrame) {
  cv::Mat dynamic(120, 160, CV_8UC1, cv::Scalar(0));
  cv::circle(dynamic, {40, 30}, 9, cv::Scalar(200), cv::FILLED);
  cv::rectangle(dynamic, cv::Rect(150, 100, 10, 20), cv::Scalar(1), cv::FILLED);  // at the edge
  cv::Mat binary;
  cv::threshold(dynamic, binary, 0, 255, cv::THRESH_BINARY);
  for (int radius : {0, 1, 6}) {
    cv::Mat expected = binary.clone();
    if (radius > 0) {
      cv::dilate(
          binary, expected,
          cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1)));
    }
    const cv::Mat dilated = dilateDynamicMask(dynamic, radius);
    ASSERT_EQ(dilated.type(), CV_8UC1);
    EXPECT_EQ(cv::countNonZero(dilated != expected), 0) << "radius " << radius;
  }
  EXPECT_TRUE(dilateDynamicMask(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), 3).empty());
  EXPECT_TRUE(dilateDynamicMask(cv::Mat(), 3).empty());
  EXPECT_THROW(dilateDynamicMask(cv::Mat(10, 10, CV_16UC1, cv::Scalar(1)), 3),
               std::invalid_argument);
}

// One StaticMask serves frame after frame (the extractor's): each assign answers as a fresh mask
// of that frame would, an empty mask included.
TEST(FeatureStaticMask, AssignedFrameAfterFrameAnswersAsAFreshMask) {
  cv::Mat first(60, 80, CV_8UC1, cv::Scalar(0));
  cv::circle(first, {20, 20}, 5, cv::Scalar(255), cv::FILLED);
  cv::Mat second(60, 80, CV_8UC1, cv::Scalar(0));
  cv::rectangle(second, cv::Rect(50, 30, 10, 12), cv::Scalar(7), cv::FILLED);
  StaticMask reused;
  for (const auto& [mask, radius] :
       std::vector<std::pair<cv::Mat, int>>{{first, 4}, {second, 4}, {cv::Mat(), 4}, {first, 2}}) {
    reused.assign(mask, radius);
    const StaticMask fresh(mask, radius);
    EXPECT_EQ(reused.everythingStatic(), fresh.everythingStatic());
    EXPECT_EQ(reused.radius(), radius);
    int mismatches = 0;
    for (int y = 0; y < first.rows; ++y) {
      for (int x = 0; x < first.cols; ++x)
        mismatches += reused.isStatic({x, y}) != fresh.isStatic({x, y});
    }
    EXPECT_EQ(mismatches, 0) << "radius " << radius;
  }
}

TEST(FeatureStaticMask, RejectsBadInput) {
  EXPECT_THROW(StaticMask(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), -1), std::invalid_argument);
  EXPECT_THROW(StaticMask(cv::Mat(10, 10, CV_32FC1, cv::Scalar(0)), 2), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::feature
