#include "segslam/io/timestamp_association.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

namespace segslam::io {
namespace {

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

// associate.py written out literally: all pairs, sorted, taken greedily. The reference for the
// windowed implementation.
Pairs associateAllPairs(const std::vector<double>& first, const std::vector<double>& second,
                        double max_difference, double offset) {
  std::vector<std::tuple<double, double, double, std::size_t, std::size_t>> candidates;
  for (std::size_t i = 0; i < first.size(); ++i) {
    for (std::size_t j = 0; j < second.size(); ++j) {
      const double diff = std::abs(first[i] - (second[j] + offset));
      if (diff < max_difference) candidates.emplace_back(diff, first[i], second[j], i, j);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> used_first(first.size());
  std::vector<bool> used_second(second.size());
  Pairs pairs;
  for (const auto& [diff, a, b, i, j] : candidates) {
    if (used_first[i] || used_second[j]) continue;
    used_first[i] = used_second[j] = true;
    pairs.emplace_back(i, j);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

TEST(TimestampAssociation, ClosestPairsAreTakenFirst) {
  // 0.010 is closer to 0.006 than 0.0 is, so 0.0 goes without.
  EXPECT_EQ(associateTimestamps({0.0, 0.010}, {0.006}, 0.02), (Pairs{{1, 0}}));
  EXPECT_EQ(associateTimestamps({0.0, 0.033, 0.066}, {0.005, 0.030, 0.070}, 0.02),
            (Pairs{{0, 0}, {1, 1}, {2, 2}}));
}

TEST(TimestampAssociation, GreedyPairsCanCross) {
  // (0.011, 0.010) is the closest pair; 0.015 then takes 0.0: the depth order is reversed.
  EXPECT_EQ(associateTimestamps({0.011, 0.015}, {0.0, 0.010}, 0.02), (Pairs{{0, 1}, {1, 0}}));
}

TEST(TimestampAssociation, TiesGoToTheEarlierTimestamp) {
  // Binary-exact values so that the differences tie exactly.
  EXPECT_EQ(associateTimestamps({0.0, 0.5}, {0.25}, 1.0), (Pairs{{0, 0}}));
  EXPECT_EQ(associateTimestamps({0.25}, {0.0, 0.5}, 1.0), (Pairs{{0, 0}}));
}

TEST(TimestampAssociation, OffsetIsAddedToTheSecondList) {
  EXPECT_EQ(associateTimestamps({10.0}, {0.0, 9.0}, 0.5, 1.0), (Pairs{{0, 1}}));
  EXPECT_TRUE(associateTimestamps({10.0}, {9.0}, 0.5).empty());
}

TEST(TimestampAssociation, MaxDifferenceIsStrict) {
  EXPECT_TRUE(associateTimestamps({0.0}, {0.5}, 0.5).empty());
  EXPECT_EQ(associateTimestamps({0.0}, {0.5}, 0.5000001), (Pairs{{0, 0}}));
  EXPECT_TRUE(associateTimestamps({0.5}, {0.0}, 0.5).empty());
}

TEST(TimestampAssociation, EmptyInputsGiveNoPairs) {
  EXPECT_TRUE(associateTimestamps({}, {1.0}, 0.02).empty());
  EXPECT_TRUE(associateTimestamps({1.0}, {}, 0.02).empty());
}

TEST(TimestampAssociation, MatchesTheAllPairsReferenceOnRandomStreams) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> step(0.001, 0.05);
  std::uniform_real_distribution<double> offset(-0.03, 0.03);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> first{1305031102.0};
    std::vector<double> second{1305031102.0 + offset(rng)};
    for (int i = 0; i < 60; ++i) {
      first.push_back(first.back() + step(rng));
      second.push_back(second.back() + step(rng));
    }
    const double o = trial % 2 == 0 ? 0.0 : offset(rng);
    ASSERT_EQ(associateTimestamps(first, second, 0.02, o),
              associateAllPairs(first, second, 0.02, o))
        << "trial " << trial;
  }
}

}  // namespace
}  // namespace segslam::io
