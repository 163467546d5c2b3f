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

TEST(Pose, OrthonormalisedRestoresARotationBlockAndKeepsTheTranslation) {
  Pose drifted = Pose::Identity();
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  drifted.linear() = 1.01 * rotation;
  drifted.translation() = Eigen::Vector3d(1, 2, 3);
  const Pose fixed = orthonormalised(drifted);
  EXPECT_NEAR(fixed.linear().determinant(), 1.0, 1e-12);
  EXPECT_NEAR((fixed.linear() * fixed.linear().transpose() - Eigen::Matrix3d::Identity()).norm(),
              0.0, 1e-12);
  EXPECT_NEAR((fixed.linear() - rotation).norm(), 0.0, 1e-9);
  EXPECT_EQ(fixed.translation(), drifted.translation());
}

TEST(Pose, ConstantVelocityExtrapolationStaysRigidOverManyFrames) {
  // velocity = T_k T_{k-1}^-1, T_{k+1} = velocity T_k: without re-orthonormalisation rounding
  // errors grow about 2.4x per step and the scale of the rotation block explodes.
  Pose previous = Pose::Identity();
  Pose current = Pose::Identity();
  current.linear() = Eigen::AngleAxisd(0.01, Eigen::Vector3d(0.2, 1, 0.1).normalized()).matrix();
  current.translation() = Eigen::Vector3d(0.01, 0.0, 0.005);
  for (int frame = 0; frame < 200; ++frame) {
    const Pose velocity = orthonormalised(current * previous.inverse());
    previous = current;
    current = orthonormalised(velocity * current);
  }
  EXPECT_NEAR(current.linear().determinant(), 1.0, 1e-9);
}

}  // namespace
}  // namespace segslam::geometry
