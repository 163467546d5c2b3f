#include "segslam/synth/texture.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace segslam::synth {
namespace {

cv::Mat checkerImage(int size, int cell) {
  cv::Mat image(size, size, CV_8UC3);
  for (int r = 0; r < size; ++r) {
    for (int c = 0; c < size; ++c) {
      const std::uint8_t value = ((r / cell + c / cell) % 2) ? 255 : 0;
      image.at<cv::Vec3b>(r, c) = cv::Vec3b(value, value, value);
    }
  }
  return image;
}

TEST(SynthTexture, BuildsMipLevelsDownToOneTexel) {
  const Texture texture(cv::Mat(64, 32, CV_8UC3, cv::Scalar(10, 20, 30)), 0.005);
  ASSERT_GE(texture.levelCount(), 6);
  EXPECT_EQ(texture.level(1).size(), cv::Size(16, 32));
  EXPECT_EQ(texture.level(texture.levelCount() - 1).cols, 1);
}

TEST(SynthTexture, SamplesTexelCentresExactlyWhenMagnified) {
  cv::Mat image(2, 2, CV_8UC3);
  image.at<cv::Vec3b>(0, 0) = {0, 0, 0};
  image.at<cv::Vec3b>(0, 1) = {100, 0, 0};
  image.at<cv::Vec3b>(1, 0) = {0, 100, 0};
  image.at<cv::Vec3b>(1, 1) = {0, 0, 100};
  const Texture texture(image, 0.01);
  // Texel (i, j) is centred at ((i + 0.5) * texel, (j + 0.5) * texel) metres.
  EXPECT_FLOAT_EQ(texture.sample(0.015, 0.005, 0.001).x(), 100.0f);
  EXPECT_FLOAT_EQ(texture.sample(0.005, 0.015, 0.001).y(), 100.0f);
  // Half-way between the four centres: their mean.
  const Eigen::Vector3f middle = texture.sample(0.01, 0.01, 0.001);
  EXPECT_FLOAT_EQ(middle.x(), 25.0f);
  EXPECT_FLOAT_EQ(middle.y(), 25.0f);
  EXPECT_FLOAT_EQ(middle.z(), 25.0f);
  // Beyond the border the border texels repeat.
  EXPECT_FLOAT_EQ(texture.sample(-1.0, -1.0, 0.001).x(), 0.0f);
}

TEST(SynthTexture, LargeFootprintsAverageInsteadOfAliasing) {
  const Texture texture(checkerImage(256, 1), 0.005);
  // Each pixel covers 16 texels: every sample must be close to the mean grey, wherever it falls.
  for (double s = 0.1; s < 1.1; s += 0.0371) {
    const Eigen::Vector3f colour = texture.sample(s, 0.5 * s + 0.2, 16 * 0.005);
    EXPECT_NEAR(colour.x(), 127.5f, 12.0f) << "at s = " << s;
  }
  // With a texel-sized footprint the checker stays sharp.
  const Eigen::Vector3f sharp = texture.sample(1.5 * 0.005, 0.5 * 0.005, 0.005);
  EXPECT_FLOAT_EQ(sharp.x(), 255.0f);
}

TEST(SynthTexture, RejectsWrongImages) {
  EXPECT_THROW(Texture(cv::Mat(), 0.005), std::invalid_argument);
  EXPECT_THROW(Texture(cv::Mat(4, 4, CV_8UC1), 0.005), std::invalid_argument);
  EXPECT_THROW(Texture(cv::Mat(4, 4, CV_8UC3), 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::synth
