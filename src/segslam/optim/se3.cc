#include "segslam/optim/se3.h"

#include <Eigen/Geometry>
#include <cmath>

namespace segslam::optim {
namespace {

// Below this angle the closed forms lose digits to cancellation (t - sin t, 1 - cos t); the
// Taylor series take over, truncated where the next term is below 1e-17.
constexpr double kSeriesAngle = 0.1;

// The coefficients of exp: R = I + a W + b W^2 and V = I + b W + c W^2, with W = skew(phi).
struct ExpCoefficients {
  double a;  // sin(t) / t
  double b;  // (1 - cos(t)) / t^2
  double c;  // (t - sin(t)) / t^3
};

ExpCoefficients expCoefficients(double angle) {
  const double t2 = angle * angle;
  if (angle < kSeriesAngle) {
    return {1.0 - t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0))),
            0.5 - t2 / 24.0 * (1.0 - t2 / 30.0 * (1.0 - t2 / 56.0 * (1.0 - t2 / 90.0))),
            1.0 / 6.0 - t2 / 120.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0 * (1.0 - t2 / 110.0)))};
  }
  return {std::sin(angle) / angle, (1.0 - std::cos(angle)) / t2,
          (angle - std::sin(angle)) / (t2 * angle)};
}

// V^-1 = I - W / 2 + d W^2, the inverse of the left Jacobian V that maps rho to translation;
// d = (1 - (t / 2) cot(t / 2)) / t^2.
double inverseLeftJacobianCoefficient(double angle) {
  const double t2 = angle * angle;
  if (angle < kSeriesAngle) {
    return 1.0 / 12.0 +
           t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 * (1.0 / 1209600.0 + t2 / 47900160.0)));
  }
  return (1.0 - angle * std::sin(angle) / (2.0 * (1.0 - std::cos(angle)))) / t2;
}

// Rotation vector (axis times angle, angle in [0, pi]) of a rotation matrix.
Eigen::Vector3d logSo3(const Eigen::Matrix3d& rotation) {
  // Through the quaternion: atan2 of its vector and scalar parts stays accurate at tiny angles
  // and near pi, where acos of the trace does not.
  Eigen::Quaterniond q(rotation);
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double sin_half = q.vec().norm();
  // angle / sin_half tends to 2 / w as the angle vanishes.
  const double scale =
      sin_half < 1e-12 ? 2.0 / q.w() : 2.0 * std::atan2(sin_half, q.w()) / sin_half;
  return scale * q.vec();
}

}  // namespace

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

geometry::Pose expSe3(const Vector6d& twist) {
  const Eigen::Vector3d phi = twist.tail<3>();
  const ExpCoefficients k = expCoefficients(phi.norm());
  const Eigen::Matrix3d w = skew(phi);
  const Eigen::Matrix3d w2 = w * w;
  geometry::Pose pose = geometry::Pose::Identity();
  pose.linear() = Eigen::Matrix3d::Identity() + k.a * w + k.b * w2;
  pose.translation() = (Eigen::Matrix3d::Identity() + k.b * w + k.c * w2) * twist.head<3>();
  return pose;
}

Vector6d logSe3(const geometry::Pose& pose) {
  const Eigen::Vector3d phi = logSo3(pose.linear());
  const Eigen::Matrix3d w = skew(phi);
  const Eigen::Matrix3d inverse_v =
      Eigen::Matrix3d::Identity() - 0.5 * w + inverseLeftJacobianCoefficient(phi.norm()) * w * w;
  Vector6d twist;
  twist << inverse_v * pose.translation(), phi;
  return twist;
}

}  // namespace segslam::optim
