#include "segslam/optim/reprojection.h"

#include <gtest/gtest.h>

#include "segslam/optim/se3.h"

namespace segslam::optim {
namespace {

const Eigen::Vector3d kPoint(0.4, -0.3, 2.5);

TEST(Reprojection, PredictsPixelAndVirtualRightColumn) {
  StereoIntrinsics k;
  const Eigen::Vector3d predicted = predictMeasurement(k, kPoint);
  EXPECT_DOUBLE_EQ(predicted.x(), k.fx * 0.4 / 2.5 + k.cx);
  EXPECT_DOUBLE_EQ(predicted.y(), k.fy * -0.3 / 2.5 + k.cy);
  EXPECT_DOUBLE_EQ(predicted.z(), predicted.x() - k.bf / 2.5);
}

TEST(Reprojection, ResidualAndChi2IgnoreTheMissingDepth) {
  StereoIntrinsics k;
  RgbdObservation observation;
  const Eigen::Vector3d predicted = predictMeasurement(k, kPoint);
  observation.pixel = predicted.head<2>() + Eigen::Vector2d(1.0, -2.0);
  observation.information = 0.5;
  EXPECT_TRUE(
      reprojectionResidual(k, observation, kPoint).isApprox(Eigen::Vector3d(1.0, -2.0, 0.0)));
  EXPECT_DOUBLE_EQ(reprojectionChi2(k, observation, kPoint), 0.5 * 5.0);
  observation.right_u = predicted.z() + 3.0;
  EXPECT_DOUBLE_EQ(reprojectionChi2(k, observation, kPoint), 0.5 * 14.0);
}

TEST(Reprojection, InlierNeedsTheChi2TestAndAPointInFront) {
  StereoIntrinsics k;
  RgbdObservation observation;
  observation.pixel = predictMeasurement(k, kPoint).head<2>() + Eigen::Vector2d(2.0, 0.0);
  EXPECT_TRUE(isInlierObservation(k, observation, kPoint));  // chi2 4 < 5.991
  observation.pixel.x() += 0.5;
  EXPECT_FALSE(isInlierObservation(k, observation, kPoint));  // chi2 6.25
  EXPECT_FALSE(isInlierObservation(k, observation, Eigen::Vector3d(0.0, 0.0, -1.0)));
}

TEST(Reprojection, PointJacobianMatchesFiniteDifferences) {
  StereoIntrinsics k;
  const Eigen::Matrix3d analytic = predictMeasurementJacobian(k, kPoint);
  constexpr double kStep = 1e-6;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d delta = kStep * Eigen::Vector3d::Unit(i);
    const Eigen::Vector3d numeric =
        (predictMeasurement(k, kPoint + delta) - predictMeasurement(k, kPoint - delta)) /
        (2.0 * kStep);
    EXPECT_TRUE(analytic.col(i).isApprox(numeric, 1e-6)) << i;
  }
}

TEST(Reprojection, PoseJacobianMatchesFiniteDifferencesOfTheLeftPerturbation) {
  StereoIntrinsics k;
  Vector6d twist;
  twist << 0.1, -0.2, 0.3, 0.05, -0.1, 0.2;
  const geometry::Pose T_cw = expSe3(twist);
  const Eigen::Vector3d p_w = T_cw.inverse() * kPoint;
  const Eigen::Matrix<double, 3, 6> analytic = predictMeasurementPoseJacobian(k, kPoint);
  constexpr double kStep = 1e-6;
  for (int i = 0; i < 6; ++i) {
    const Vector6d delta = kStep * Vector6d::Unit(i);
    const Eigen::Vector3d numeric = (predictMeasurement(k, expSe3(delta) * T_cw * p_w) -
                                     predictMeasurement(k, expSe3(-delta) * T_cw * p_w)) /
                                    (2.0 * kStep);
    EXPECT_TRUE(analytic.col(i).isApprox(numeric, 1e-6)) << i;
  }
}

}  // namespace
}  // namespace segslam::optim
