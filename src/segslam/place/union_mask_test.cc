#include "segslam/place/union_mask.h"

#include <gtest/gtest.h>

#include "segslam/util/error.h"

namespace segslam::place {
namespace {

TEST(UnionMask, StaticOnlyWhereStaticInBoth) {
  cv::Mat a(2, 2, CV_8UC1, cv::Scalar(255));
  cv::Mat b(2, 2, CV_8UC1, cv::Scalar(255));
  a.at<uchar>(0, 0) = 0;
  b.at<uchar>(1, 1) = 0;
  const cv::Mat both = unionStaticMask(a, b);
  EXPECT_EQ(both.at<uchar>(0, 0), 0);
  EXPECT_EQ(both.at<uchar>(1, 1), 0);
  EXPECT_EQ(both.at<uchar>(0, 1), 255);
  EXPECT_EQ(both.at<uchar>(1, 0), 255);
}

TEST(UnionMask, EmptyMeansAllStatic) {
  const cv::Mat a(2, 2, CV_8UC1, cv::Scalar(0));
  EXPECT_EQ(cv::countNonZero(unionStaticMask(a, cv::Mat()) != a), 0);
  EXPECT_TRUE(unionStaticMask(cv::Mat(), cv::Mat()).empty());
  EXPECT_THROW((void)unionStaticMask(a, cv::Mat(3, 2, CV_8UC1)), util::Error);
}

TEST(UnionMask, StaticFractionPerCell) {
  // 4 x 4 mask, left half static except one pixel; on a 2 x 2 grid.
  cv::Mat mask(4, 4, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(0, 0, 2, 4)).setTo(255);
  mask.at<uchar>(0, 0) = 0;
  const cv::Mat fraction = staticFraction(mask, cv::Size(2, 2));
  EXPECT_FLOAT_EQ(fraction.at<float>(0, 0), 0.75f);
  EXPECT_FLOAT_EQ(fraction.at<float>(1, 0), 1.0f);
  EXPECT_FLOAT_EQ(fraction.at<float>(0, 1), 0.0f);
  EXPECT_FLOAT_EQ(fraction.at<float>(1, 1), 0.0f);
  const cv::Mat all = staticFraction(cv::Mat(), cv::Size(3, 2));
  EXPECT_EQ(all.size(), cv::Size(3, 2));
  EXPECT_DOUBLE_EQ(cv::sum(all)[0], 6.0);
}

TEST(UnionMask, ErosionGrowsTheDynamicArea) {
  cv::Mat mask(20, 20, CV_8UC1, cv::Scalar(255));
  mask.at<uchar>(10, 10) = 0;
  const cv::Mat eroded = erodeStaticMask(mask, 3);
  EXPECT_EQ(eroded.at<uchar>(10, 13), 0);
  EXPECT_EQ(eroded.at<uchar>(10, 14), 255);
  EXPECT_EQ(eroded.at<uchar>(0, 0), 255);  // the image border is not a moving object
  EXPECT_EQ(cv::countNonZero(erodeStaticMask(mask, 0) != mask), 0);
}

}  // namespace
}  // namespace segslam::place
