#include "segslam/feature/mask_dilation.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace segslam::feature {
namespace {

// Sparse dots and a few blobs, some touching the border.
cv::Mat randomMask(cv::Size size, int seed) {
  cv::RNG rng(seed);
  cv::Mat mask = cv::Mat::zeros(size, CV_8UC1);
  for (int i = 0; i < 12; ++i) {
    mask.at<std::uint8_t>(rng.uniform(0, size.height), rng.uniform(0, size.width)) = 7;
  }
  for (int i = 0; i < 3; ++i) {
    const cv::Point centre(rng.uniform(0, size.width), rng.uniform(0, size.height));
    cv::circle(mask, centre, rng.uniform(2, 30), cv::Scalar(255), cv::FILLED);
  }
  return mask;
}

TEST(MaskDilation, TheSamePixelsAsOpenCvsEllipticDilation) {
  for (const int radius : {0, 1, 3, 10, 24}) {
    for (int seed = 0; seed < 5; ++seed) {
      const cv::Mat mask = randomMask({157, 121}, seed);
      cv::Mat expected;
      cv::dilate(
          mask != 0, expected,
          cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1)));
      const cv::Mat dilated = dilateByRows(mask, ellipseHalfWidths(radius));
      EXPECT_EQ(cv::countNonZero(dilated != expected), 0) << "radius " << radius;
    }
  }
}

TEST(MaskDilation, TheDiscHoldsThePixelsWithinTheRadius) {
  for (const int radius : {1, 4, 9, 48}) {
    const cv::Mat mask = randomMask({200, 150}, radius);
    cv::Mat distance;
    cv::distanceTransform(mask == 0, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    const cv::Mat expected = distance <= static_cast<float>(radius);
    const cv::Mat dilated = dilateByRows(mask, discHalfWidths(radius));
    EXPECT_EQ(cv::countNonZero(dilated != expected), 0) << "radius " << radius;
  }
}

TEST(MaskDilation, AWindowOfALargerImageSeesNothingOutsideIt) {
  cv::Mat image = cv::Mat::zeros(60, 60, CV_8UC1);
  image.at<std::uint8_t>(10, 10) = 255;  // outside the window, 5 px from its corner
  image.at<std::uint8_t>(40, 40) = 255;
  const cv::Mat dilated = dilateByRows(image(cv::Rect(14, 14, 40, 40)), discHalfWidths(8));
  EXPECT_EQ(dilated.at<std::uint8_t>(0, 0), 0);
  EXPECT_EQ(dilated.at<std::uint8_t>(26, 26), 255);
  EXPECT_EQ(
      cv::countNonZero(dilated),
      cv::countNonZero(dilateByRows(image(cv::Rect(14, 14, 40, 40)).clone(), discHalfWidths(8))));
}

TEST(MaskDilation, DiscRowsAreCutAtTheRadius) {
  EXPECT_EQ(discHalfWidths(0), RowHalfWidths({0}));
  EXPECT_EQ(discHalfWidths(2), RowHalfWidths({0, 1, 2, 1, 0}));
  EXPECT_EQ(discHalfWidths(3), RowHalfWidths({0, 2, 2, 3, 2, 2, 0}));
}

TEST(MaskDilation, RefusesOtherImagesAndEvenElements) {
  EXPECT_THROW(dilateByRows(cv::Mat::zeros(5, 5, CV_16UC1), {0}), std::invalid_argument);
  EXPECT_THROW(dilateByRows(cv::Mat::zeros(5, 5, CV_8UC1), {0, 1}), std::invalid_argument);
  EXPECT_THROW(dilateByRows(cv::Mat::zeros(5, 5, CV_8UC1), discHalfWidths(300)),
               std::invalid_argument);
}

}  // namespace
}  // namespace segslam::feature
