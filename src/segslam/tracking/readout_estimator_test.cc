#include "segslam/tracking/readout_estimator.h"

#include <gtest/gtest.h>

namespace segslam::tracking {
namespace {

// A frame's evidence when the true readout is `truth`: its Gauss-Newton step from `readout_s`
// lands on the truth.
ReadoutEvidence evidenceFor(double truth, double readout_s, double information) {
  return {readout_s, information * (truth - readout_s), information};
}

TEST(ReadoutEstimator, StartsAtTheCameraReadoutAndHoldsItWithoutEvidence) {
  ReadoutEstimator estimator(0.02, 1.0 / 30.0);
  EXPECT_DOUBLE_EQ(estimator.readout(), 0.02);
  for (int i = 0; i < 100; ++i) estimator.addFrame({estimator.readout(), 0.0, 0.0});
  EXPECT_DOUBLE_EQ(estimator.readout(), 0.02);
}

TEST(ReadoutEstimator, FollowsTheFramesToAnotherReadoutAndBack) {
  ReadoutEstimator estimator(0.02, 1.0 / 30.0);
  // Frames played backwards: the last row is read first.
  for (int i = 0; i < 100; ++i) estimator.addFrame(evidenceFor(-0.025, estimator.readout(), 1.0e6));
  EXPECT_NEAR(estimator.readout(), -0.025, 0.001);
  for (int i = 0; i < 100; ++i) estimator.addFrame(evidenceFor(0.012, estimator.readout(), 1.0e6));
  EXPECT_NEAR(estimator.readout(), 0.012, 0.001);
}

TEST(ReadoutEstimator, WeighsFramesByTheirInformation) {
  ReadoutEstimator estimator(0.02, 1.0 / 30.0, {0.95, 0.0});
  estimator.addFrame(evidenceFor(0.03, 0.02, 3.0e6));
  estimator.addFrame(evidenceFor(0.01, 0.02, 1.0e6));
  // (0.95 * 3 * 0.03 + 1 * 0.01) / (0.95 * 3 + 1)
  EXPECT_NEAR(estimator.readout(), (0.95 * 3.0 * 0.03 + 0.01) / (0.95 * 3.0 + 1.0), 1e-12);
}

TEST(ReadoutEstimator, StaysWithinAFramePeriod) {
  ReadoutEstimator estimator(0.02, 1.0 / 30.0);
  for (int i = 0; i < 50; ++i) estimator.addFrame(evidenceFor(0.5, estimator.readout(), 1.0e6));
  EXPECT_DOUBLE_EQ(estimator.readout(), 1.0 / 30.0);
}

TEST(ReadoutEstimator, LeavesAGlobalShutterAlone) {
  ReadoutEstimator estimator(0.0, 1.0 / 30.0);
  for (int i = 0; i < 50; ++i) estimator.addFrame(evidenceFor(0.02, estimator.readout(), 1.0e6));
  EXPECT_DOUBLE_EQ(estimator.readout(), 0.0);
}

}  // namespace
}  // namespace segslam::tracking
