#include "segslam/segmentation/strongest_corners.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::segmentation {
namespace {

std::vector<cv::Point2f> opencvCorners(const cv::Mat& gray, int max_corners, double quality,
                                       double min_distance) {
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(gray, corners, max_corners, quality, min_distance);
  return corners;
}

void expectSameCorners(const cv::Mat& gray, int max_corners, double quality, double min_distance) {
  const auto ours = strongestCorners(gray, max_corners, quality, min_distance);
  const auto theirs = opencvCorners(gray, max_corners, quality, min_distance);
  ASSERT_EQ(ours.size(), theirs.size());
  for (std::size_t i = 0; i < ours.size(); ++i) {
    ASSERT_EQ(ours[i], theirs[i]) << "corner " << i;
  }
}

cv::Mat texture(cv::Size size, int seed, double blur) {
  cv::Mat noise(size, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), blur);
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  return noise;
}

TEST(StrongestCorners, AreOpenCVsCornersInOpenCVsOrder) {
  for (int seed = 1; seed <= 4; ++seed) {
    const cv::Mat gray = texture(cv::Size(640, 480), seed, 1.0 + seed * 0.5);
    expectSameCorners(gray, 400, 0.01, 10.0);
    expectSameCorners(gray, 0, 0.05, 4.0);
    expectSameCorners(gray, 50, 0.01, 0.5);
  }
}

TEST(StrongestCorners, HandleImagesOfAnyHeightAndPlateaus) {
  // Heights around the band size, and flat squares whose equal maxima OpenCV orders by position.
  for (int rows : {3, 31, 32, 33, 65, 97}) {
    cv::Mat gray = texture(cv::Size(120, rows), rows, 1.0);
    expectSameCorners(gray, 100, 0.01, 3.0);
  }
  cv::Mat squares(200, 200, CV_8UC1, cv::Scalar(0));
  for (int y = 20; y < 180; y += 40) {
    for (int x = 20; x < 180; x += 40) squares(cv::Rect(x, y, 15, 15)).setTo(255);
  }
  expectSameCorners(squares, 0, 0.01, 5.0);
  EXPECT_TRUE(strongestCorners(cv::Mat(50, 50, CV_8UC1, cv::Scalar(7)), 10, 0.01, 5).empty());
}

TEST(StrongestCorners, AreOpenCVsOnARealFrame) {
  SEGSLAM_REQUIRE_SHARED(dataset, "tum_fr1_xyz_300");
  for (const char* name : {"rgb/1305031102.175304.jpg", "rgb/1305031108.811244.jpg"}) {
    const cv::Mat image = cv::imread((dataset / name).string(), cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(image.empty()) << name;
    expectSameCorners(image, 400, 0.01, 10.0);
  }
}

TEST(StrongestCorners, RefuseColourImages) {
  EXPECT_THROW(strongestCorners(cv::Mat(10, 10, CV_8UC3), 10, 0.01, 5), util::Error);
}

}  // namespace
}  // namespace segslam::segmentation
