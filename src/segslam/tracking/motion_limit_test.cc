#include "segslam/tracking/motion_limit.h"

#include <gtest/gtest.h>

namespace segslam::tracking {
namespace {

// World-to-camera pose of a camera whose centre is at x metres on the world's x axis.
geometry::Pose cameraAt(double x) {
  geometry::Pose T_wc = geometry::Pose::Identity();
  T_wc.translation().x() = x;
  return T_wc.inverse();
}

TEST(MotionLimit, ACameraMovingAtWalkingPaceIsWithinTheLimit) {
  EXPECT_TRUE(withinMotionLimit(cameraAt(0.0), 0.0, cameraAt(0.05), 1.0 / 30.0, {}));
}

TEST(MotionLimit, AJumpOfAMetreBetweenTwoFramesIsNot) {
  EXPECT_FALSE(withinMotionLimit(cameraAt(0.0), 0.0, cameraAt(1.0), 1.0 / 30.0, {}));
}

TEST(MotionLimit, TheLimitGrowsWithTheTimeBetweenTheFrames) {
  // A second of frames dropped: a metre is possible.
  EXPECT_TRUE(withinMotionLimit(cameraAt(0.0), 0.0, cameraAt(1.0), 1.0, {}));
}

TEST(MotionLimit, ATimestampGoingBackAllowsOnlyTheNoiseMargin) {
  EXPECT_TRUE(withinMotionLimit(cameraAt(0.0), 1.0, cameraAt(0.02), 0.5, {}));
  EXPECT_FALSE(withinMotionLimit(cameraAt(0.0), 1.0, cameraAt(0.2), 0.5, {}));
}

TEST(MotionLimit, NoLimitWhenTheSpeedIsZero) {
  MotionLimitOptions options;
  options.max_speed_m_per_s = 0.0;
  EXPECT_TRUE(withinMotionLimit(cameraAt(0.0), 0.0, cameraAt(5.0), 1.0 / 30.0, options));
}

}  // namespace
}  // namespace segslam::tracking
