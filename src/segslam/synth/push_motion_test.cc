#include "segslam/synth/push_motion.h"

#include <gtest/gtest.h>

namespace segslam::synth {
namespace {

TEST(SynthPushMotion, RestsGlidesAndRestsAgain) {
  PushMotion push;
  push.end.translation() = Eigen::Vector3d(0.6, 0.0, 0.0);
  push.end.linear() = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  push.begin_time = 1.0;
  push.end_time = 3.0;
  EXPECT_TRUE(push.at(0.0).isApprox(push.start, 0.0));
  EXPECT_TRUE(push.at(1.0).isApprox(push.start, 0.0));
  EXPECT_TRUE(push.at(3.0).isApprox(push.end, 0.0));
  EXPECT_TRUE(push.at(9.0).isApprox(push.end, 0.0));
  const geometry::Pose middle = push.at(2.0);
  EXPECT_NEAR(middle.translation().x(), 0.3, 1e-12);
  EXPECT_NEAR(geometry::rotationAngleAccurate(middle), 0.1, 1e-12);
  // Eases in: slower at the start than on average.
  EXPECT_LT(push.at(1.1).translation().x(), 0.6 * 0.1 / 2.0);
}

TEST(SynthPushMotion, EmptyWindowNeverMoves) {
  PushMotion push;
  push.end.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  EXPECT_TRUE(push.at(5.0).isApprox(push.start, 0.0));
}

}  // namespace
}  // namespace segslam::synth
