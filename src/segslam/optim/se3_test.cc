#include "segslam/optim/se3.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace segslam::optim {
namespace {

Vector6d randomTwist(std::mt19937& rng, double max_angle) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const Eigen::Vector3d axis =
      Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
  Vector6d twist;
  twist << uniform(rng), uniform(rng), uniform(rng), std::abs(uniform(rng)) * max_angle * axis;
  return twist;
}

TEST(Se3, SkewIsTheCrossProduct) {
  const Eigen::Vector3d a(1.0, -2.0, 3.0);
  const Eigen::Vector3d b(0.5, 4.0, -1.0);
  EXPECT_TRUE((skew(a) * b).isApprox(a.cross(b)));
}

TEST(Se3, RotationPartMatchesAngleAxis) {
  Vector6d twist;
  twist << 0.0, 0.0, 0.0, 0.3, -0.4, 1.2;
  const Eigen::Vector3d phi = twist.tail<3>();
  const Eigen::Matrix3d expected =
      Eigen::AngleAxisd(phi.norm(), phi.normalized()).toRotationMatrix();
  EXPECT_TRUE(expSe3(twist).linear().isApprox(expected, 1e-14));
  EXPECT_TRUE(expSe3(twist).translation().isZero(0.0));
}

TEST(Se3, RoundTripsForGeneralTwists) {
  std::mt19937 rng(1);
  for (int i = 0; i < 200; ++i) {
    const Vector6d twist = randomTwist(rng, M_PI - 1e-3);
    EXPECT_TRUE(logSe3(expSe3(twist)).isApprox(twist, 1e-9)) << twist.transpose();
  }
}

TEST(Se3, RoundTripsForTinyAndZeroAngles) {
  std::mt19937 rng(2);
  for (const double angle : {0.0, 1e-12, 1e-8, 1e-5, 9e-5, 1.1e-4, 1e-3}) {
    Vector6d twist = randomTwist(rng, 1.0);
    twist.tail<3>() = angle * twist.tail<3>().normalized();
    const Vector6d round_trip = logSe3(expSe3(twist));
    EXPECT_NEAR((round_trip - twist).norm(), 0.0, 1e-14) << angle;
  }
}

TEST(Se3, ExpOfSmallTwistIsTheFirstOrderPerturbation) {
  Vector6d twist;
  twist << 1e-7, -2e-7, 3e-7, 2e-7, 1e-7, -1e-7;
  const Eigen::Vector3d p(1.0, 2.0, 3.0);
  const Eigen::Vector3d expected = p + twist.head<3>() + twist.tail<3>().cross(p);
  EXPECT_NEAR((expSe3(twist) * p - expected).norm(), 0.0, 1e-12);
}

TEST(Se3, ExpSe3IsAProperRigidMotion) {
  std::mt19937 rng(3);
  const geometry::Pose pose = expSe3(randomTwist(rng, 3.0));
  EXPECT_NEAR(pose.linear().determinant(), 1.0, 1e-12);
  EXPECT_TRUE((pose.linear() * pose.linear().transpose()).isIdentity(1e-12));
}

TEST(Se3, RoundTripsNearAHalfTurn) {
  Vector6d twist;
  twist << 0.5, -1.0, 2.0, (M_PI - 1e-9) * Eigen::Vector3d(1.0, 2.0, -2.0).normalized();
  EXPECT_TRUE(logSe3(expSe3(twist)).isApprox(twist, 1e-8));
}

}  // namespace
}  // namespace segslam::optim
