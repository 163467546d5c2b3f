#include "segslam/optim/reprojection_cost.h"

#include <ceres/sized_cost_function.h>

#include <Eigen/Geometry>
#include <cmath>

#include "segslam/optim/reprojection.h"
#include "segslam/optim/se3.h"

namespace segslam::optim {
namespace {

// d(R(q) p) / d(x, y, z, w) for a unit quaternion q = (v, w), from
// R(q) p = p + 2 w (v x p) + 2 v x (v x p) and v x (v x p) = v (v.p) - p (v.v).
Eigen::Matrix<double, 3, 4> rotatedPointQuaternionJacobian(const Eigen::Quaterniond& q,
                                                           const Eigen::Vector3d& p) {
  const Eigen::Vector3d v = q.vec();
  Eigen::Matrix<double, 3, 4> jacobian;
  jacobian.leftCols<3>() =
      -2.0 * q.w() * skew(p) +
      2.0 * (v.dot(p) * Eigen::Matrix3d::Identity() + v * p.transpose() - 2.0 * p * v.transpose());
  jacobian.col(3) = 2.0 * v.cross(p);
  return jacobian;
}

// Ceres lays a Jacobian block out row by row.
template <int kParameters>
using JacobianMap = Eigen::Map<Eigen::Matrix<double, 3, kParameters, Eigen::RowMajor>>;

class ReprojectionCost final : public ceres::SizedCostFunction<3, 4, 3, 3> {
 public:
  ReprojectionCost(const StereoIntrinsics& intrinsics, const RgbdObservation& observation)
      : intrinsics_(intrinsics),
        observation_(observation),
        sqrt_information_(std::sqrt(observation.information)) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Quaterniond> q(parameters[0]);
    const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
    const Eigen::Map<const Eigen::Vector3d> p_w(parameters[2]);
    const Eigen::Matrix3d rotation = q.toRotationMatrix();
    const Eigen::Vector3d p_c = rotation * p_w + t;
    if (!isInFront(p_c)) return false;

    Eigen::Map<Eigen::Vector3d> residual(residuals);
    residual = sqrt_information_ * reprojectionResidual(intrinsics_, observation_, p_c);
    if (jacobians == nullptr) return true;

    // d residual / d p_c; the three parameter blocks chain onto it.
    Eigen::Matrix3d d_p_c = -sqrt_information_ * predictMeasurementJacobian(intrinsics_, p_c);
    if (!observation_.hasDepth()) d_p_c.row(2).setZero();
    if (jacobians[0] != nullptr) {
      JacobianMap<4> d_rotation(jacobians[0]);
      d_rotation = d_p_c * rotatedPointQuaternionJacobian(Eigen::Quaterniond(q), p_w);
    }
    if (jacobians[1] != nullptr) {
      JacobianMap<3> d_translation(jacobians[1]);
      d_translation = d_p_c;
    }
    if (jacobians[2] != nullptr) {
      JacobianMap<3> d_point(jacobians[2]);
      d_point = d_p_c * rotation;
    }
    return true;
  }

 private:
  StereoIntrinsics intrinsics_;
  RgbdObservation observation_;
  double sqrt_information_;
};

}  // namespace

std::unique_ptr<ceres::CostFunction> makeReprojectionCost(const StereoIntrinsics& intrinsics,
                                                          const RgbdObservation& observation) {
  return std::make_unique<ReprojectionCost>(intrinsics, observation);
}

}  // namespace segslam::optim
