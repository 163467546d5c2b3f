#include "segslam/optim/pose_optimizer.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <utility>

#include "segslam/optim/reprojection.h"
#include "segslam/optim/se3.h"

namespace segslam::optim {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Fewer observations than this leave the 6-dof pose (nearly) unconstrained: keep the pose.
constexpr int kMinObservationsToOptimise = 3;
// Convergence: a step shorter than this (metres and radians, far below any noise level) or a
// predicted cost decrease below this share of the cost.
constexpr double kConvergedStepNorm = 1e-6;
constexpr double kConvergedCostDecrease = 1e-6;
// Damping lambda scales diag(H) (Marquardt), so it is dimensionless; start close to Gauss-Newton.
constexpr double kInitialDamping = 1e-5;
constexpr double kMaxDamping = 1e12;
const double kMonoHuberWidth = std::sqrt(kChi2Mono);
const double kStereoHuberWidth = std::sqrt(kChi2Stereo);

// The normal equations of the active observations at one pose, and their robust cost.
struct Linearisation {
  Matrix6d hessian = Matrix6d::Zero();   // sum of w J^T Omega J
  Vector6d gradient = Vector6d::Zero();  // sum of w J^T Omega e
  double cost = 0.0;                     // sum of rho(chi2)
  bool valid = true;                     // false when an active point is not in front
};

// Huber's rho on chi2 = s (g2o's convention, width delta on the weighted residual's norm) and
// its derivative, which is the iteratively reweighted least-squares weight.
struct RobustChi2 {
  double cost;
  double weight;
};

RobustChi2 huber(double chi2, double delta) {
  if (chi2 <= delta * delta) return {chi2, 1.0};
  const double norm = std::sqrt(chi2);
  return {2.0 * delta * norm - delta * delta, delta / norm};
}

// Convergence test before paying for an evaluation: the step is tiny, or the decrease that the
// quadratic model predicts for it, -g.dx - dx.H.dx / 2, is a negligible share of the cost.
bool isNegligible(const Vector6d& step, const Linearisation& at) {
  const double predicted_decrease = -step.dot(at.gradient) - 0.5 * step.dot(at.hessian * step);
  return step.norm() < kConvergedStepNorm || predicted_decrease < kConvergedCostDecrease * at.cost;
}

// Adds weight J^T J to the hessian's upper triangle (mirrored once all observations are in, by
// completeHessian) and -weight J^T residual to the gradient. Loops over the raw coefficients
// rather than Eigen's product expressions: this runs for every observation in every iteration,
// and those expressions cost a function call per coefficient where the compiler does not inline
// them (the sanitizer build at -O1, where they were a tenth of whole-sequence tests' time).
template <int kRows>
void addWeighted(const Eigen::Matrix<double, kRows, 6>& jacobian,
                 const Eigen::Matrix<double, kRows, 1>& residual, double weight,
                 Linearisation& result) {
  const double* j = jacobian.data();  // column-major: J(r, c) = j[c * kRows + r]
  const double* e = residual.data();
  double* hessian = result.hessian.data();
  double* gradient = result.gradient.data();
  for (int c = 0; c < 6; ++c) {
    const double* column_c = j + c * kRows;
    for (int d = c; d < 6; ++d) {
      const double* column_d = j + d * kRows;
      double sum = 0.0;
      for (int r = 0; r < kRows; ++r) sum += column_c[r] * column_d[r];
      hessian[d * 6 + c] += weight * sum;
    }
    double projected = 0.0;
    for (int r = 0; r < kRows; ++r) projected += column_c[r] * e[r];
    gradient[c] -= weight * projected;
  }
}

// J^T J is symmetric: its lower triangle is the upper one's mirror, summed in the same order.
void completeHessian(Linearisation& result) {
  for (int c = 0; c < 6; ++c) {
    for (int d = c + 1; d < 6; ++d) result.hessian(d, c) = result.hessian(c, d);
  }
}

class PoseProblem {
 public:
  PoseProblem(const StereoIntrinsics& intrinsics, const std::vector<PoseObservation>& observations)
      : intrinsics_(intrinsics), observations_(observations) {}

  // Linearises the observations flagged `active`, with the Huber kernel when `robust`.
  [[nodiscard]] Linearisation linearise(const geometry::Pose& T_cw, const std::vector<bool>& active,
                                        bool robust) const {
    Linearisation result;
    for (std::size_t i = 0; i < observations_.size(); ++i) {
      if (!active[i]) continue;
      const RgbdObservation& observation = observations_[i].observation;
      const Eigen::Vector3d p_c = T_cw * observations_[i].point_w;
      if (!isInFront(p_c)) {
        result.valid = false;
        return result;
      }
      if (observation.hasDepth()) {
        accumulate<3>(observation, p_c, robust ? kStereoHuberWidth : 0.0, result);
      } else {
        accumulate<2>(observation, p_c, robust ? kMonoHuberWidth : 0.0, result);
      }
    }
    completeHessian(result);
    return result;
  }

  // Labels every observation (active or not) at `T_cw`; returns the number of inliers.
  int classify(const geometry::Pose& T_cw, std::vector<bool>& inlier) const {
    int num_inliers = 0;
    for (std::size_t i = 0; i < observations_.size(); ++i) {
      const Eigen::Vector3d p_c = T_cw * observations_[i].point_w;
      inlier[i] = isInlierObservation(intrinsics_, observations_[i].observation, p_c);
      num_inliers += inlier[i] ? 1 : 0;
    }
    return num_inliers;
  }

  // Levenberg-Marquardt from T_cw over the active observations. A step is taken only if it
  // lowers the cost and keeps every active point in front of the camera.
  void minimise(geometry::Pose& T_cw, const std::vector<bool>& active, bool robust,
                int iterations) const {
    Linearisation current = linearise(T_cw, active, robust);
    if (!current.valid) return;
    double lambda = kInitialDamping;
    for (int iteration = 0; iteration < iterations && lambda < kMaxDamping; ++iteration) {
      Matrix6d damped = current.hessian;
      // Marquardt's scaling, plus a floor so that a direction without information stays put.
      damped.diagonal() += lambda * (current.hessian.diagonal().array() + 1e-9).matrix();
      const Vector6d step = damped.ldlt().solve(-current.gradient);
      if (!step.allFinite() || isNegligible(step, current)) return;
      const geometry::Pose candidate = geometry::orthonormalised(expSe3(step) * T_cw);
      Linearisation next = linearise(candidate, active, robust);
      if (next.valid && next.cost < current.cost) {
        T_cw = candidate;
        current = next;
        lambda = std::max(lambda / 3.0, kInitialDamping);
      } else {
        lambda *= 4.0;
      }
    }
  }

 private:
  // Adds one observation with `kRows` residual rows (2 without depth, 3 with); huber_width 0
  // means no robust kernel. The residual's Jacobian is minus the prediction's.
  template <int kRows>
  void accumulate(const RgbdObservation& observation, const Eigen::Vector3d& p_c,
                  double huber_width, Linearisation& result) const {
    const Eigen::Matrix<double, kRows, 1> residual =
        reprojectionResidual(intrinsics_, observation, p_c).template head<kRows>();
    const double chi2 = observation.information * residual.squaredNorm();
    const RobustChi2 robust_chi2 =
        huber_width > 0.0 ? huber(chi2, huber_width) : RobustChi2{chi2, 1.0};
    const Eigen::Matrix<double, kRows, 6> d_predicted =
        predictMeasurementPoseJacobian(intrinsics_, p_c).template topRows<kRows>();
    addWeighted(d_predicted, residual, robust_chi2.weight * observation.information, result);
    result.cost += robust_chi2.cost;
  }

  const StereoIntrinsics& intrinsics_;
  const std::vector<PoseObservation>& observations_;
};

}  // namespace

PoseOptimizationResult optimizePose(const StereoIntrinsics& intrinsics,
                                    const geometry::Pose& initial_T_cw,
                                    const std::vector<PoseObservation>& observations,
                                    const PoseOptimizationOptions& options) {
  const PoseProblem problem(intrinsics, observations);
  PoseOptimizationResult result{initial_T_cw, {}, 0};
  // The first round starts from every observation whose point is in front of the camera.
  std::vector<bool> active(observations.size());
  for (std::size_t i = 0; i < observations.size(); ++i) {
    active[i] = isInFront(initial_T_cw * observations[i].point_w);
  }
  int num_active = static_cast<int>(std::count(active.begin(), active.end(), true));
  for (int round = 0; round < options.rounds; ++round) {
    if (num_active >= kMinObservationsToOptimise) {
      const bool robust = round + 1 < options.rounds;
      problem.minimise(result.T_cw, active, robust, options.iterations_per_round);
    }
    num_active = problem.classify(result.T_cw, active);
  }
  result.inlier = std::move(active);
  result.num_inliers = num_active;
  return result;
}

}  // namespace segslam::optim
