#include "segslam/geometry/pose.h"

#include <gtest/gtest.h>

#include <cmath>

namespace segslam::geometry {
namespace {

TEST(Pose, FromTranslationAndUnnormalisedQuaternion) {
  const Eigen::Quaterniond q(2.0, 0.0, 0.0, 2.0);  // 90 deg about z, scaled by 2*sqrt(2)
  const Pose pose = poseFromTranslationQuaternion({1, 2, 3}, q);
  EXPECT_NEAR((pose * Eigen::Vector3d(1, 0, 0) - Eigen::Vector3d(1, 3, 3)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(rotationAngle(pose), M_PI / 2, 1e-12);
}

TEST(Pose, RotationAngleIsClampedAndAccurateVariantHandlesTinyAngles) {
  EXPECT_DOUBLE_EQ(rotationAngle(Pose::Identity()), 0.0);
  Pose tiny = Pose::Identity();
  tiny.linear() = Eigen::AngleAxisd(1e-7, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_NEAR(rotationAngleAccurate(tiny), 1e-7, 1e-12);
  Pose half_turn = Pose::Identity();
  half_turn.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_NEAR(rotationAngle(half_turn), M_PI, 1e-7);
}

}  // namespace
}  // namespace segslam::geometry
