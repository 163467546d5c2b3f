#include "segslam/eval/nice_ticks.h"

#include <gtest/gtest.h>

namespace segslam::eval {
namespace {

TEST(SvgTicks, StepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(niceStep(1.0, 5), 0.2);
  EXPECT_DOUBLE_EQ(niceStep(0.3, 5), 0.1);
  EXPECT_DOUBLE_EQ(niceStep(23.0, 5), 5.0);
  EXPECT_DOUBLE_EQ(niceStep(0.07, 5), 0.02);
  EXPECT_DOUBLE_EQ(niceStep(100.0, 5), 20.0);
}

TEST(SvgTicks, AxisWidensToWholeSteps) {
  const auto axis = niceAxis(0.013, 0.087, 4);
  EXPECT_DOUBLE_EQ(axis.step, 0.02);
  EXPECT_NEAR(axis.low, 0.0, 1e-12);
  EXPECT_NEAR(axis.high, 0.1, 1e-12);
}

TEST(SvgTicks, ConstantDataStillGetsARange) {
  const auto axis = niceAxis(2.0, 2.0);
  EXPECT_LT(axis.low, 2.0);
  EXPECT_GT(axis.high, 2.0);
  const auto zero = niceAxis(0.0, 0.0);
  EXPECT_LT(zero.low, 0.0);
  EXPECT_GT(zero.high, 0.0);
}

TEST(SvgTicks, TickValuesAndLabels) {
  const auto ticks = tickValues(-0.25, 0.31, 0.1);
  ASSERT_EQ(ticks.size(), 6u);
  EXPECT_NEAR(ticks.front(), -0.2, 1e-12);
  EXPECT_NEAR(ticks.back(), 0.3, 1e-12);
  EXPECT_EQ(formatTick(ticks[2], 0.1), "0.0");
  EXPECT_EQ(formatTick(0.15, 0.05), "0.15");
  EXPECT_EQ(formatTick(15.0, 5.0), "15");
  EXPECT_EQ(formatTick(-0.0, 1.0), "0");
}

}  // namespace
}  // namespace segslam::eval
