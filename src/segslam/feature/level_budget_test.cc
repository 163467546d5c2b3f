#include "segslam/feature/level_budget.h"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

namespace segslam::feature {
namespace {

int sum(const std::vector<int>& values) { return std::accumulate(values.begin(), values.end(), 0); }

TEST(FeatureLevelBudget, SharesFollowLevelArea) {
  const ScaleLevels levels(8, 1.2);
  const std::vector<int> shares = levelFeatureShares(1000, levels);
  ASSERT_EQ(shares.size(), 8u);
  EXPECT_EQ(sum(shares), 1000);
  // Geometric series with ratio 1 / 1.44: 1000 (1 - r) / (1 - r^8) at level 0.
  EXPECT_NEAR(shares[0], 323.5, 1.0);
  for (std::size_t level = 1; level < shares.size(); ++level) {
    EXPECT_NEAR(shares[level], shares[level - 1] / 1.44, 1.0) << "level " << level;
  }
  EXPECT_EQ(levelFeatureShares(7, ScaleLevels(1, 1.2)), std::vector<int>{7});
}

TEST(FeatureLevelBudget, ShortLevelsHandTheirShareToOthers) {
  const std::vector<int> shares = {500, 300, 200};
  EXPECT_EQ(allocateLevelBudgets(shares, {1000, 1000, 1000}), shares);
  // Level 1 has only 100 candidates: its other 200 go to levels 0 and 2 in ratio 500 : 200.
  const std::vector<int> budgets = allocateLevelBudgets(shares, {1000, 100, 1000});
  EXPECT_EQ(budgets[1], 100);
  EXPECT_EQ(sum(budgets), 1000);
  EXPECT_NEAR(budgets[0] - 500, 143, 1);
  // Not enough candidates in total: everything is used.
  EXPECT_EQ(allocateLevelBudgets(shares, {50, 100, 20}), (std::vector<int>{50, 100, 20}));
  // A level with capacity left but a rounded share of 0 still takes spare features.
  EXPECT_EQ(allocateLevelBudgets({3, 0}, {1, 5}), (std::vector<int>{1, 2}));
  EXPECT_THROW(allocateLevelBudgets({1, 2}, {1}), std::invalid_argument);
}

TEST(FeatureScaleLevels, FactorsAndSigmas) {
  const ScaleLevels levels(3, 1.5);
  EXPECT_EQ(levels.numLevels(), 3);
  EXPECT_DOUBLE_EQ(levels.scales()[2], 2.25);
  EXPECT_DOUBLE_EQ(levels.inverseScales()[1], 1.0 / 1.5);
  EXPECT_DOUBLE_EQ(levels.sigma2()[2], 2.25 * 2.25);
  EXPECT_DOUBLE_EQ(levels.inverseSigma2()[0], 1.0);
  EXPECT_THROW(ScaleLevels(0, 1.2), std::invalid_argument);
  EXPECT_THROW(ScaleLevels(8, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::feature
