#include "segslam/eval/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace segslam::eval {
namespace {

TEST(Statistics, MedianOfOddAndEvenCounts) {
  EXPECT_DOUBLE_EQ(median(std::vector<double>{3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{7.0}), 7.0);
}

TEST(Statistics, AllFiguresOfASmallList) {
  const std::vector<double> values{1.0, 2.0, 3.0, 4.0};
  const auto stats = computeStatistics(values);
  EXPECT_EQ(stats.count, 4u);
  EXPECT_DOUBLE_EQ(stats.rmse, std::sqrt(30.0 / 4.0));
  EXPECT_DOUBLE_EQ(stats.mean, 2.5);
  EXPECT_DOUBLE_EQ(stats.median, 2.5);
  EXPECT_DOUBLE_EQ(stats.std, std::sqrt(1.25));  // population: divides by n, not n - 1
  EXPECT_DOUBLE_EQ(stats.min, 1.0);
  EXPECT_DOUBLE_EQ(stats.max, 4.0);
}

TEST(Statistics, ConstantListHasZeroStd) {
  const auto stats = computeStatistics(std::vector<double>(5, 0.3));
  EXPECT_DOUBLE_EQ(stats.std, 0.0);
  EXPECT_DOUBLE_EQ(stats.rmse, 0.3);
}

TEST(Statistics, EmptyListIsAProgrammingError) {
  EXPECT_THROW(computeStatistics({}), std::invalid_argument);
}

TEST(Statistics, ShareOfNothingIsNone) {
  EXPECT_DOUBLE_EQ(share(1, 4), 0.25);
  EXPECT_DOUBLE_EQ(share(0, 0), 0.0);
}

}  // namespace
}  // namespace segslam::eval
