#include "segslam/feature/image_pyramid.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace segslam::feature {
namespace {

cv::Point2d centroid(const cv::Mat& image) {
  const cv::Moments m = cv::moments(image);
  return {m.m10 / m.m00, m.m01 / m.m00};
}

TEST(ImagePyramid, LevelToBaseMapsEveryLevelBackOntoLevelZero) {
  cv::Mat gray(480, 640, CV_8UC1, cv::Scalar(0));
  const cv::Point2d blob(401.0, 173.0);
  cv::circle(gray, cv::Point(401, 173), 12, cv::Scalar(255), cv::FILLED);
  const ScaleLevels levels(8, 1.2);
  std::vector<cv::Mat> pyramid;
  buildImagePyramid(gray, levels, pyramid);
  for (int level = 1; level < levels.numLevels(); ++level) {
    const LevelToBase to_base = LevelToBase::between(gray.size(), pyramid[level].size());
    const cv::Point2f mapped = to_base(cv::Point2f(centroid(pyramid[level])));
    EXPECT_NEAR(mapped.x, blob.x, 0.15) << "level " << level;
    EXPECT_NEAR(mapped.y, blob.y, 0.15) << "level " << level;
  }
}

TEST(ImagePyramid, LevelToBaseUsesTheRoundedLevelSize) {
  const LevelToBase to_base = LevelToBase::between({640, 480}, {533, 400});
  EXPECT_FLOAT_EQ(to_base.x_factor, 640.0f / 533.0f);
  EXPECT_FLOAT_EQ(to_base.y_factor, 1.2f);
  EXPECT_FLOAT_EQ(to_base(cv::Point2f(-0.5f, -0.5f)).x, -0.5f);  // the image corner stays put
}

}  // namespace
}  // namespace segslam::feature
