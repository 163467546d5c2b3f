#include "segslam/segmentation/busy_share.h"

#include <gtest/gtest.h>

namespace segslam::segmentation {
namespace {

TEST(BusyShare, IsZeroUntilAnIntervalIsKnown) {
  BusyShare share;
  EXPECT_EQ(share.value(), 0.0);
  share.sample(1.0, 10.0);
  EXPECT_EQ(share.value(), 0.0);
}

TEST(BusyShare, AThreadThatNeverWaitsIsFullyBusy) {
  BusyShare share;
  for (int i = 0; i <= 10; ++i) share.sample(0.01 * i, 5.0 + 0.01 * i);
  EXPECT_NEAR(share.value(), 1.0, 1e-9);
}

TEST(BusyShare, AThreadPacedByACameraIsMostlyIdle) {
  BusyShare share;
  // 10 ms of work per 33 ms frame.
  for (int i = 0; i <= 30; ++i) share.sample(0.010 * i, 0.033 * i);
  EXPECT_NEAR(share.value(), 0.010 / 0.033, 1e-9);
}

TEST(BusyShare, FollowsAChangeOfLoadWithinAFewIntervals) {
  BusyShare share(0.5);
  double cpu = 0.0;
  double wall = 0.0;
  share.sample(cpu, wall);
  for (int i = 0; i < 10; ++i) share.sample(cpu += 0.01, wall += 0.04);
  EXPECT_NEAR(share.value(), 0.25, 1e-3);
  for (int i = 0; i < 10; ++i) share.sample(cpu += 0.01, wall += 0.01);
  EXPECT_GT(share.value(), 0.99);
}

TEST(BusyShare, LeavesOutTheTimeBeforeARestart) {
  BusyShare share;
  share.sample(0.0, 0.0);
  share.restart(0.0, 0.2);  // 200 ms waiting: not counted
  share.sample(0.01, 0.21);
  EXPECT_EQ(share.value(), 1.0);
}

TEST(BusyShare, ClockRoundingNeverGivesMoreThanFullyBusy) {
  BusyShare share;
  share.sample(0.0, 0.0);
  share.sample(0.011, 0.010);
  EXPECT_EQ(share.value(), 1.0);
  share.sample(0.011, 0.010);  // no wall time passed: ignored
  EXPECT_EQ(share.value(), 1.0);
}

}  // namespace
}  // namespace segslam::segmentation
