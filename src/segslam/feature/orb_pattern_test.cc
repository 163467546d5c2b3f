#include "segslam/feature/orb_pattern.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>

#include "segslam/feature/feature_test_images.h"
#include "segslam/feature/orb_descriptor.h"

namespace segslam::feature {
namespace {

TEST(OrbPattern, LearnedTableIsWellFormed) {
  const OrbPattern& pattern = learnedOrbPattern();
  std::set<std::tuple<int, int, int, int>> distinct;
  for (const BinaryTest& test : pattern) {
    for (const PatternPoint point : {test.first, test.second}) {
      EXPECT_LE(point.x * point.x + point.y * point.y, kPatternRadius * kPatternRadius);
    }
    // The learning tool keeps the two points of a test at least 5 px apart in x or y.
    EXPECT_GE(
        std::max(std::abs(test.first.x - test.second.x), std::abs(test.first.y - test.second.y)),
        5);
    distinct.emplace(test.first.x, test.first.y, test.second.x, test.second.y);
  }
  EXPECT_EQ(distinct.size(), pattern.size());
}

TEST(OrbPattern, SteeringRoundsLikeCvRound) {
  for (const float value : {0.5f, 1.5f, 2.5f, -0.5f, -1.5f, 3.49f, -7.51f, 14.999f}) {
    EXPECT_EQ(static_cast<int>(roundHalfEven(value)), cvRound(value)) << value;
  }
  const PatternPoint point{10, -3};
  for (int degrees = 0; degrees < 360; degrees += 7) {
    const float radians = static_cast<float>(degrees * CV_PI / 180.0);
    const float c = std::cos(radians);
    const float s = std::sin(radians);
    const cv::Point steered = steerPatternPoint(point, c, s);
    EXPECT_EQ(steered.x, cvRound(10.0f * c + 3.0f * s));
    EXPECT_EQ(steered.y, cvRound(10.0f * s - 3.0f * c));
  }
}

// The descriptor samples exactly the pixels steerPatternPoint names, which is what the pattern
// was learned on.
TEST(OrbPattern, SteeredBriefEvaluatesTheSteeredTests) {
  const cv::Mat image = testing::texturedImage({80, 80}, 9);
  const SteeredBrief brief(learnedOrbPattern());
  const cv::Point center(40, 40);
  for (const float degrees : {0.0f, 13.0f, 90.0f, 181.5f, 333.3f}) {
    std::uint8_t descriptor[kDescriptorBytes];
    brief.compute(image, center, degrees, descriptor);
    const double radians = degrees * CV_PI / 180.0;
    const auto c = static_cast<float>(std::cos(radians));
    const auto s = static_cast<float>(std::sin(radians));
    for (int i = 0; i < kDescriptorBits; ++i) {
      const BinaryTest& test = learnedOrbPattern()[i];
      const bool expected = image.at<std::uint8_t>(center + steerPatternPoint(test.first, c, s)) <
                            image.at<std::uint8_t>(center + steerPatternPoint(test.second, c, s));
      EXPECT_EQ(((descriptor[i / 8] >> (i % 8)) & 1) != 0, expected) << degrees << " test " << i;
    }
  }
}

}  // namespace
}  // namespace segslam::feature
