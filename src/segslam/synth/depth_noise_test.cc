#include "segslam/synth/depth_noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "segslam/util/error.h"

namespace segslam::synth {
namespace {

cv::Mat constantDepth(double z, int width = 200, int height = 150) {
  return cv::Mat(height, width, CV_64FC1, cv::Scalar(z));
}

TEST(SynthDepthNoise, NoneQuantisesExactly) {
  cv::Mat z = constantDepth(1.23456);
  z.at<double>(0, 0) = 0.0;   // nothing hit
  z.at<double>(0, 1) = 14.0;  // beyond 16 bits at 5000 per metre
  z.at<double>(0, 2) = 0.00005;
  const cv::Mat depth = depthImage(z, DepthNoise::kNone, 5000.0, 1);
  ASSERT_EQ(depth.type(), CV_16UC1);
  EXPECT_EQ(depth.at<std::uint16_t>(5, 5), 6173);  // round(6172.8)
  EXPECT_EQ(depth.at<std::uint16_t>(0, 0), 0);
  EXPECT_EQ(depth.at<std::uint16_t>(0, 1), 0);
  EXPECT_EQ(depth.at<std::uint16_t>(0, 2), 0);
}

TEST(SynthDepthNoise, KinectNoiseHasTheModelledSpread) {
  const double z = 3.0;
  const cv::Mat depth = depthImage(constantDepth(z), DepthNoise::kKinect, 5000.0, 42);
  double sum = 0.0;
  double sum_squares = 0.0;
  int count = 0;
  // Border pixels have fewer neighbours but no discontinuity either: all are valid.
  for (auto it = depth.begin<std::uint16_t>(); it != depth.end<std::uint16_t>(); ++it) {
    ASSERT_GT(*it, 0);
    const double error = *it / 5000.0 - z;
    sum += error;
    sum_squares += error * error;
    ++count;
  }
  const double mean = sum / count;
  const double sigma = std::sqrt(sum_squares / count - mean * mean);
  EXPECT_NEAR(kinectDepthSigma(z), 0.0012 + 0.0019 * 2.6 * 2.6, 1e-12);
  EXPECT_NEAR(mean, 0.0, 0.0005);
  EXPECT_NEAR(sigma, kinectDepthSigma(z), 0.05 * kinectDepthSigma(z));
}

TEST(SynthDepthNoise, KinectHasNoDepthOutOfRangeAndAtDiscontinuities) {
  cv::Mat z = constantDepth(2.0, 40, 30);
  z(cv::Rect(0, 0, 20, 30)).setTo(1.0);  // a step at column 20
  z.at<double>(15, 5) = 0.3;             // too near
  z.at<double>(15, 30) = 8.5;            // too far
  const cv::Mat depth = depthImage(z, DepthNoise::kKinect, 5000.0, 1);
  EXPECT_EQ(depth.at<std::uint16_t>(10, 19), 0);
  EXPECT_EQ(depth.at<std::uint16_t>(10, 20), 0);
  EXPECT_GT(depth.at<std::uint16_t>(10, 18), 0);
  EXPECT_GT(depth.at<std::uint16_t>(10, 21), 0);
  EXPECT_EQ(depth.at<std::uint16_t>(15, 5), 0);
  EXPECT_EQ(depth.at<std::uint16_t>(15, 30), 0);
  // Their neighbours see a jump too.
  EXPECT_EQ(depth.at<std::uint16_t>(15, 6), 0);
}

TEST(SynthDepthNoise, KinectNoiseFollowsTheSeed) {
  const cv::Mat z = constantDepth(2.5);
  const cv::Mat a = depthImage(z, DepthNoise::kKinect, 5000.0, 9);
  const cv::Mat b = depthImage(z, DepthNoise::kKinect, 5000.0, 9);
  const cv::Mat c = depthImage(z, DepthNoise::kKinect, 5000.0, 10);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);
}

TEST(SynthDepthNoise, NamesMapToModels) {
  EXPECT_EQ(depthNoiseFromName("none"), DepthNoise::kNone);
  EXPECT_EQ(depthNoiseFromName("kinect"), DepthNoise::kKinect);
  EXPECT_THROW(depthNoiseFromName("Kinect"), util::Error);
}

}  // namespace
}  // namespace segslam::synth
