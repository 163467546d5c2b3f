#include "segslam/eval/rpe_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "segslam/eval/test_trajectories.h"

namespace segslam::eval {
namespace {

using Pairs = std::vector<PosePair>;

TEST(RpePairs, PairsEndingAtTheLastPoseAreDropped) {
  const std::vector<double> frames{0, 1, 2, 3, 4};
  // (3, 4) ends at the last pose and (4, 4) too: the tool drops both.
  EXPECT_EQ(fixedDeltaPairs(frames, 1.0), (Pairs{{0, 1}, {1, 2}, {2, 3}}));
  EXPECT_EQ(fixedDeltaPairs(frames, 2.0), (Pairs{{0, 2}, {1, 3}}));
}

TEST(RpePairs, ADeltaShorterThanTheSpacingPairsAPoseWithItself) {
  const std::vector<double> stamps{10.0, 11.0, 12.0};
  EXPECT_EQ(fixedDeltaPairs(stamps, 0.2), (Pairs{{0, 0}, {1, 1}}));
}

TEST(RpePairs, SecondsAndFramesDiffer) {
  const auto estimate = fixtures::alongX(fixtures::stampsFrom(5.0, 0.5, 6), {0, 1, 2, 3, 4, 5});
  EXPECT_EQ(deltaIndex(estimate, DeltaUnit::kSeconds), estimate.timestamps());
  EXPECT_EQ(deltaIndex(estimate, DeltaUnit::kFrames), (std::vector<double>{0, 1, 2, 3, 4, 5}));
  // 1 s is two poses at 2 Hz; 1 frame is the next pose.
  EXPECT_EQ(fixedDeltaPairs(deltaIndex(estimate, DeltaUnit::kSeconds), 1.0),
            (Pairs{{0, 2}, {1, 3}, {2, 4}}));
  EXPECT_EQ(fixedDeltaPairs(deltaIndex(estimate, DeltaUnit::kFrames), 1.0),
            (Pairs{{0, 1}, {1, 2}, {2, 3}, {3, 4}}));
}

TEST(RpePairs, DistanceAndRotationAccumulateAlongTheEstimate) {
  core::Trajectory estimate;
  estimate.append(0.0, fixtures::poseAt({0.0, 0.0, 0.0}, 0.0));
  estimate.append(1.0, fixtures::poseAt({1.0, 0.0, 0.0}, 10.0));
  estimate.append(2.0, fixtures::poseAt({1.0, 2.0, 0.0}, 30.0));
  const auto metres = deltaIndex(estimate, DeltaUnit::kMeters);
  ASSERT_EQ(metres.size(), 3u);
  EXPECT_DOUBLE_EQ(metres[0], 0.0);
  EXPECT_NEAR(metres[1], 1.0, 1e-12);
  EXPECT_NEAR(metres[2], 3.0, 1e-12);
  const auto degrees = deltaIndex(estimate, DeltaUnit::kDegrees);
  EXPECT_NEAR(degrees[1], 10.0, 1e-6);
  EXPECT_NEAR(degrees[2], 30.0, 1e-6);
  const auto radians = deltaIndex(estimate, DeltaUnit::kRadians);
  EXPECT_NEAR(radians[2], 30.0 * std::numbers::pi / 180.0, 1e-8);
}

TEST(RpePairs, AllPairsForFewPosesElseSeededRandomOnes) {
  std::mt19937_64 rng(1);
  EXPECT_EQ(allOrRandomPairs(3, 10000, rng).size(), 9u);  // 3 < sqrt(10000)
  EXPECT_EQ(allOrRandomPairs(3, 0, rng).size(), 9u);      // 0: no limit
  std::mt19937_64 first(42);
  std::mt19937_64 second(42);
  const auto sampled = allOrRandomPairs(200, 50, first);
  EXPECT_EQ(sampled.size(), 50u);
  EXPECT_EQ(sampled, allOrRandomPairs(200, 50, second));
  for (const auto& [i, j] : sampled) {
    EXPECT_LT(i, 200u);
    EXPECT_LT(j, 200u);
  }
}

TEST(RpePairs, LimitSamplesWithoutReplacementInOrder) {
  Pairs pairs;
  for (std::size_t i = 0; i < 20; ++i) pairs.emplace_back(i, i + 1);
  std::mt19937_64 rng(3);
  const auto limited = limitPairs(pairs, 5, rng);
  ASSERT_EQ(limited.size(), 5u);
  EXPECT_TRUE(std::is_sorted(limited.begin(), limited.end()));
  EXPECT_EQ(std::adjacent_find(limited.begin(), limited.end()), limited.end());
  EXPECT_EQ(limitPairs(pairs, 0, rng), pairs);
  EXPECT_EQ(limitPairs(pairs, 20, rng), pairs);
}

TEST(RpePairs, UnitNamesRoundTrip) {
  for (const auto& name : deltaUnitNames()) {
    const auto unit = parseDeltaUnit(name);
    ASSERT_TRUE(unit.has_value());
    EXPECT_EQ(deltaUnitName(*unit), name);
  }
  EXPECT_FALSE(parseDeltaUnit("km").has_value());
}

}  // namespace
}  // namespace segslam::eval
