#include "segslam/feature/orb_pattern_learning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace segslam::feature {
namespace {

// Patches whose "intensity" at point i is drawn independently per point, except that point 3
// copies point 0: tests 0-vs-k and 3-vs-k are then the same test.
PatchSamples syntheticSamples(int patches) {
  const std::vector<PatternPoint> points = {{-10, 0}, {0, 0}, {10, 0}, {0, 10}, {0, -10}};
  PatchSamples samples(points);
  cv::RNG rng(4);
  for (int patch = 0; patch < patches; ++patch) {
    cv::Mat image(31, 31, CV_8UC1, cv::Scalar(0));
    for (const PatternPoint& point : points) {
      image.at<std::uint8_t>(15 + point.y, 15 + point.x) =
          static_cast<std::uint8_t>(rng.uniform(0, 256));
    }
    image.at<std::uint8_t>(15 + 10, 15 + 0) = image.at<std::uint8_t>(15, 15 - 10);  // copy point 0
    samples.addPatch(image, {15, 15}, 0.0f);
  }
  return samples;
}

TEST(OrbPatternLearning, CandidatePointsFillTheDisc) {
  const auto points = patternCandidatePoints();
  int expected = 0;
  for (int y = -kPatternRadius; y <= kPatternRadius; ++y) {
    for (int x = -kPatternRadius; x <= kPatternRadius; ++x) {
      expected += x * x + y * y <= kPatternRadius * kPatternRadius;
    }
  }
  EXPECT_EQ(static_cast<int>(points.size()), expected);
}

TEST(OrbPatternLearning, SamplesAreSteered) {
  PatchSamples samples({{5, 0}});
  cv::Mat image(31, 31, CV_8UC1, cv::Scalar(0));
  image.at<std::uint8_t>(15 + 5, 15) = 200;  // (0, 5) from the centre: (5, 0) turned by 90 degrees
  samples.addPatch(image, {15, 15}, 90.0f);
  samples.addPatch(image, {15, 15}, 0.0f);
  ASSERT_EQ(samples.patchCount(), 2);
  EXPECT_EQ(samples.intensities(0).at<std::uint8_t>(0), 200);
  EXPECT_EQ(samples.intensities(0).at<std::uint8_t>(1), 0);
}

TEST(OrbPatternLearning, PicksUncorrelatedTestsNearOneHalf) {
  const PatchSamples samples = syntheticSamples(2000);
  PatternLearningOptions options;
  options.num_tests = 4;
  options.min_point_separation = 1;
  options.max_correlation = 0.1;
  const LearnedTests learned = learnBinaryTests(samples, options);
  ASSERT_EQ(learned.tests.size(), 4u);
  EXPECT_EQ(learned.candidate_tests, 10);  // 5 points, all pairs far enough apart
  for (const double mean : learned.means) EXPECT_NEAR(mean, 0.5, 0.05);
  // Point 3 duplicates point 0, so (0, 3) is constant and never picked, and no two picked tests
  // are the same test under different names.
  const PatternStatistics statistics = patternStatistics(samples, learned.tests);
  EXPECT_LT(statistics.max_abs_correlation, 0.6);
  for (const BinaryTest& test : learned.tests) {
    const bool zero_vs_three = (test.first.x == -10 && test.second.y == 10) ||
                               (test.first.y == 10 && test.second.x == -10);
    EXPECT_FALSE(zero_vs_three);
  }
}

TEST(OrbPatternLearning, RaisesTheThresholdUntilEnoughTestsAreFound) {
  const PatchSamples samples = syntheticSamples(500);
  PatternLearningOptions options;
  options.num_tests = 8;
  options.min_point_separation = 1;
  options.max_correlation = 0.0;
  options.correlation_step = 0.05;
  const LearnedTests learned = learnBinaryTests(samples, options);
  EXPECT_EQ(learned.tests.size(), 8u);
  EXPECT_GT(learned.max_correlation, 0.0);
  options.num_tests = 11;  // more than the 10 candidates
  EXPECT_THROW(learnBinaryTests(samples, options), std::invalid_argument);
  EXPECT_THROW(learnBinaryTests(PatchSamples({{0, 0}, {5, 5}}), {}), std::invalid_argument);
}

TEST(OrbPatternLearning, StatisticsOfAPerfectlyCorrelatedPair) {
  const PatchSamples samples = syntheticSamples(1000);
  // (0 < 1) and (3 < 1) are the same test: correlation 1.
  const std::vector<BinaryTest> tests = {{{-10, 0}, {0, 0}}, {{0, 10}, {0, 0}}};
  const PatternStatistics statistics = patternStatistics(samples, tests);
  EXPECT_NEAR(statistics.max_abs_correlation, 1.0, 1e-9);
  EXPECT_LT(statistics.mean_abs_bias, 0.05);
  EXPECT_THROW(patternStatistics(samples, {{{1, 1}, {0, 0}}}), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::feature
