#include "segslam/eval/closest_index.h"

#include <gtest/gtest.h>

#include <vector>

namespace segslam::eval {
namespace {

TEST(RpeClosestIndex, FindsExactAndNearestValues) {
  const std::vector<double> stamps{1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_EQ(findClosestIndex(stamps, 3.0), 2u);
  EXPECT_EQ(findClosestIndex(stamps, 3.4), 2u);
  EXPECT_EQ(findClosestIndex(stamps, 3.6), 3u);
  EXPECT_EQ(findClosestIndex(stamps, -10.0), 0u);
  EXPECT_EQ(findClosestIndex(stamps, 10.0), 4u);
}

TEST(RpeClosestIndex, TieKeepsTheFirstVisitedValue) {
  // The search visits 3.0 (index 2) first, then 2.0: equal distance, so index 2 stays best.
  const std::vector<double> stamps{1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(findClosestIndex(stamps, 2.5), 2u);
  // Here it visits 2.0 (index 1) first, then 3.0 at the same distance: index 1 stays.
  const std::vector<double> three{1.0, 2.0, 3.0};
  EXPECT_EQ(findClosestIndex(three, 2.5), 1u);
}

TEST(RpeClosestIndex, SingleValue) {
  const std::vector<double> one{7.0};
  EXPECT_EQ(findClosestIndex(one, 0.0), 0u);
}

}  // namespace
}  // namespace segslam::eval
