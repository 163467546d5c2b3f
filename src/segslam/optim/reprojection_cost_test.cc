#include "segslam/optim/reprojection_cost.h"

#include <ceres/manifold.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

#include "segslam/optim/reprojection.h"

namespace segslam::optim {
namespace {

// A keyframe pose and a point in front of it, as the cost function's parameter blocks.
struct Parameters {
  Eigen::Quaterniond rotation = Eigen::Quaterniond(0.9, 0.2, -0.3, 0.1).normalized();
  Eigen::Vector3d translation{0.2, -0.1, 0.5};
  Eigen::Vector3d point_w{0.4, 0.3, 2.5};

  [[nodiscard]] std::vector<const double*> blocks() const {
    return {rotation.coeffs().data(), translation.data(), point_w.data()};
  }
  [[nodiscard]] Eigen::Vector3d pointInCamera() const { return rotation * point_w + translation; }
};

RgbdObservation observationWithDepth() {
  RgbdObservation observation;
  observation.pixel = {300.0, 200.0};
  observation.right_u = 290.0;
  observation.information = 1.0 / 1.44;
  return observation;
}

struct Evaluation {
  Eigen::Vector3d residual;
  Eigen::Matrix<double, 3, 4, Eigen::RowMajor> d_rotation;
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> d_translation;
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> d_point;
};

Evaluation evaluate(const ceres::CostFunction& cost, const Parameters& parameters) {
  Evaluation result;
  std::vector<double*> jacobians = {result.d_rotation.data(), result.d_translation.data(),
                                    result.d_point.data()};
  EXPECT_TRUE(cost.Evaluate(parameters.blocks().data(), result.residual.data(), jacobians.data()));
  return result;
}

// Central differences along each block's tangent directions (the quaternion's through the
// manifold's Plus) against the analytic Jacobians mapped to the tangent space. Written out
// rather than with ceres::GradientChecker, whose Eigen members are allocated inside libceres
// and freed here, which AddressSanitizer builds of Eigen get wrong.
void expectJacobiansMatchFiniteDifferences(const RgbdObservation& observation) {
  constexpr double kStep = 1e-6;
  const Parameters at;
  ASSERT_TRUE(isInFront(at.pointInCamera()));
  const auto cost = makeReprojectionCost({}, observation);
  const Evaluation analytic = evaluate(*cost, at);
  const ceres::EigenQuaternionManifold quaternion;
  Eigen::Matrix<double, 4, 3, Eigen::RowMajor> plus_jacobian;
  quaternion.PlusJacobian(at.rotation.coeffs().data(), plus_jacobian.data());
  const Eigen::Matrix3d d_rotation_tangent = analytic.d_rotation * plus_jacobian;

  const auto difference = [&](const Parameters& plus, const Parameters& minus) -> Eigen::Vector3d {
    return (evaluate(*cost, plus).residual - evaluate(*cost, minus).residual) / (2.0 * kStep);
  };
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    const Eigen::Vector3d step = kStep * Eigen::Vector3d::Unit(i);
    const Eigen::Vector3d back = -step;
    Parameters plus = at;
    Parameters minus = at;
    quaternion.Plus(at.rotation.coeffs().data(), step.data(), plus.rotation.coeffs().data());
    quaternion.Plus(at.rotation.coeffs().data(), back.data(), minus.rotation.coeffs().data());
    EXPECT_TRUE(d_rotation_tangent.col(i).isApprox(difference(plus, minus), 1e-6));
    plus = minus = at;
    plus.translation += step;
    minus.translation -= step;
    EXPECT_TRUE(analytic.d_translation.col(i).isApprox(difference(plus, minus), 1e-6));
    plus = minus = at;
    plus.point_w += step;
    minus.point_w -= step;
    EXPECT_TRUE(analytic.d_point.col(i).isApprox(difference(plus, minus), 1e-6));
  }
}

TEST(ReprojectionCost, JacobiansWithDepth) {
  expectJacobiansMatchFiniteDifferences(observationWithDepth());
}

TEST(ReprojectionCost, JacobiansWithoutDepth) {
  RgbdObservation observation = observationWithDepth();
  observation.right_u = -1.0;
  expectJacobiansMatchFiniteDifferences(observation);
}

TEST(ReprojectionCost, ResidualIsTheWeightedReprojectionError) {
  const Parameters parameters;
  const RgbdObservation observation = observationWithDepth();
  const auto cost = makeReprojectionCost({}, observation);
  ASSERT_EQ(cost->num_residuals(), 3);
  Eigen::Vector3d residual;
  ASSERT_TRUE(cost->Evaluate(parameters.blocks().data(), residual.data(), nullptr));
  const Eigen::Vector3d expected =
      reprojectionResidual({}, observation, parameters.pointInCamera()) / 1.2;
  EXPECT_TRUE(residual.isApprox(expected, 1e-12));
  EXPECT_NEAR(residual.squaredNorm(), reprojectionChi2({}, observation, parameters.pointInCamera()),
              1e-9);
}

TEST(ReprojectionCost, WithoutDepthTheThirdRowIsZero) {
  RgbdObservation observation = observationWithDepth();
  observation.right_u = -1.0;
  const Evaluation evaluation = evaluate(*makeReprojectionCost({}, observation), Parameters{});
  EXPECT_EQ(evaluation.residual.z(), 0.0);
  EXPECT_TRUE(evaluation.d_rotation.row(2).isZero(0.0));
  EXPECT_TRUE(evaluation.d_translation.row(2).isZero(0.0));
  EXPECT_TRUE(evaluation.d_point.row(2).isZero(0.0));
  EXPECT_FALSE(evaluation.d_point.row(0).isZero());
}

TEST(ReprojectionCost, FailsForAPointBehindTheCamera) {
  Parameters parameters;
  parameters.point_w = -parameters.point_w * 3.0;
  ASSERT_FALSE(isInFront(parameters.pointInCamera()));
  const auto cost = makeReprojectionCost({}, observationWithDepth());
  Eigen::Vector3d residual;
  EXPECT_FALSE(cost->Evaluate(parameters.blocks().data(), residual.data(), nullptr));
}

}  // namespace
}  // namespace segslam::optim
