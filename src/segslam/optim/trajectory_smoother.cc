#include "segslam/optim/trajectory_smoother.h"

#include <ceres/autodiff_cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/rotation.h>
#include <ceres/solver.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace segslam::optim {
namespace {

// The rotation vector of q_a^-1 q_b: the rotation from a to b in a's frame.
template <typename T>
Eigen::Matrix<T, 3, 1> relativeRotation(const Eigen::Quaternion<T>& q_a,
                                        const Eigen::Quaternion<T>& q_b) {
  const Eigen::Quaternion<T> d = q_a.conjugate() * q_b;
  const T wxyz[4] = {d.w(), d.x(), d.y(), d.z()};
  Eigen::Matrix<T, 3, 1> rotation_vector;
  ceres::QuaternionToAngleAxis(wxyz, rotation_vector.data());
  return rotation_vector;
}

// A tracked frame's position as a measurement of the camera's.
struct TrackedPosition {
  Eigen::Vector3d measured;
  double sigma;

  template <typename T>
  bool operator()(const T* position, T* residual) const {
    for (int i = 0; i < 3; ++i) residual[i] = (position[i] - T(measured[i])) / T(sigma);
    return true;
  }
};

// A tracked frame's orientation as a measurement of the camera's (Eigen's x, y, z, w order).
struct TrackedRotation {
  Eigen::Quaterniond measured;
  double sigma_rad;

  template <typename T>
  bool operator()(const T* rotation, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q(rotation);
    const Eigen::Matrix<T, 3, 1> error =
        relativeRotation(measured.cast<T>(), Eigen::Quaternion<T>(q));
    for (int i = 0; i < 3; ++i) residual[i] = error[i] / T(sigma_rad);
    return true;
  }
};

// Three consecutive frames: the change of velocity between the two intervals, against what the
// acceleration allows over the time between the intervals' middles.
struct PositionAcceleration {
  double dt_before;
  double dt_after;
  double sigma_velocity_change;

  template <typename T>
  bool operator()(const T* p0, const T* p1, const T* p2, T* residual) const {
    for (int i = 0; i < 3; ++i) {
      const T change = (p2[i] - p1[i]) / T(dt_after) - (p1[i] - p0[i]) / T(dt_before);
      residual[i] = change / T(sigma_velocity_change);
    }
    return true;
  }
};

struct RotationAcceleration {
  double dt_before;
  double dt_after;
  double sigma_rate_change;

  template <typename T>
  bool operator()(const T* r0, const T* r1, const T* r2, T* residual) const {
    const Eigen::Quaternion<T> q0(Eigen::Map<const Eigen::Quaternion<T>>{r0});
    const Eigen::Quaternion<T> q1(Eigen::Map<const Eigen::Quaternion<T>>{r1});
    const Eigen::Quaternion<T> q2(Eigen::Map<const Eigen::Quaternion<T>>{r2});
    const Eigen::Matrix<T, 3, 1> change =
        relativeRotation(q1, q2) / T(dt_after) - relativeRotation(q0, q1) / T(dt_before);
    for (int i = 0; i < 3; ++i) residual[i] = change[i] / T(sigma_rate_change);
    return true;
  }
};

struct FrameState {
  Eigen::Vector3d position;
  Eigen::Quaterniond rotation;
};

// The solver's cost functions share one kernel and one manifold, which the problem does not own.
struct SmoothingProblem {
  SmoothingProblem() : problem(problemOptions()) {}

  static ceres::Problem::Options problemOptions() {
    ceres::Problem::Options options;
    options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    return options;
  }

  ceres::Problem problem;
  ceres::EigenQuaternionManifold quaternion_manifold;
};

// Each frame's tracked pose as a measurement of its state, with a Huber kernel.
void addTrackedPoses(std::vector<FrameState>& states, const TrajectorySmoothingOptions& options,
                     ceres::LossFunction& robust, SmoothingProblem& smoothing) {
  const double rotation_sigma_rad = options.rotation_sigma_deg * M_PI / 180.0;
  for (FrameState& state : states) {
    smoothing.problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<TrackedPosition, 3, 3>(
            new TrackedPosition{state.position, options.position_sigma_m}),
        &robust, state.position.data());
    smoothing.problem.AddResidualBlock(new ceres::AutoDiffCostFunction<TrackedRotation, 3, 4>(
                                           new TrackedRotation{state.rotation, rotation_sigma_rad}),
                                       &robust, state.rotation.coeffs().data());
    smoothing.problem.SetManifold(state.rotation.coeffs().data(), &smoothing.quaternion_manifold);
  }
}

// The accelerations between each three consecutive frames; states[k] is frame first + k.
void addAccelerations(const std::vector<core::StampedPose>& poses, std::size_t first,
                      std::vector<FrameState>& states, const TrajectorySmoothingOptions& options,
                      SmoothingProblem& smoothing) {
  for (std::size_t k = 1; k + 1 < states.size(); ++k) {
    const double dt_before = poses[first + k].timestamp - poses[first + k - 1].timestamp;
    const double dt_after = poses[first + k + 1].timestamp - poses[first + k].timestamp;
    const double span = 0.5 * (dt_before + dt_after);
    smoothing.problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PositionAcceleration, 3, 3, 3, 3>(
            new PositionAcceleration{dt_before, dt_after, options.acceleration_m_s2 * span}),
        nullptr, states[k - 1].position.data(), states[k].position.data(),
        states[k + 1].position.data());
    smoothing.problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<RotationAcceleration, 3, 4, 4, 4>(new RotationAcceleration{
            dt_before, dt_after, options.angular_acceleration_rad_s2 * span}),
        nullptr, states[k - 1].rotation.coeffs().data(), states[k].rotation.coeffs().data(),
        states[k + 1].rotation.coeffs().data());
  }
}

// The smoothed frames [begin, end) of `poses`.
std::vector<geometry::Pose> smoothWindow(const std::vector<core::StampedPose>& poses,
                                         std::size_t begin, std::size_t end,
                                         const TrajectorySmoothingOptions& options) {
  std::vector<FrameState> states;
  states.reserve(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    states.push_back(
        {poses[i].T_wc.translation(), Eigen::Quaterniond(poses[i].T_wc.linear()).normalized()});
  }
  ceres::HuberLoss robust(options.robust_sigmas);
  SmoothingProblem smoothing;
  addTrackedPoses(states, options, robust, smoothing);
  addAccelerations(poses, begin, states, options, smoothing);
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.num_threads = 1;
  solver_options.max_num_iterations = 20;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &smoothing.problem, &summary);
  std::vector<geometry::Pose> smoothed;
  smoothed.reserve(states.size());
  for (const FrameState& state : states) {
    smoothed.push_back(geometry::poseFromTranslationQuaternion(state.position, state.rotation));
  }
  return smoothed;
}

// Smooths the run of frames [begin, end) of `tracked` into `smoothed`, window by window.
void smoothRun(const std::vector<core::StampedPose>& tracked, std::size_t begin, std::size_t end,
               const TrajectorySmoothingOptions& options,
               std::vector<core::StampedPose>& smoothed) {
  const auto window = static_cast<std::size_t>(std::max(options.max_window_frames, 3));
  const auto overlap =
      std::min(static_cast<std::size_t>(std::max(options.window_overlap_frames, 0)), window / 2);
  for (std::size_t start = begin;;) {
    const std::size_t stop = end - start <= window ? end : start + window;
    const std::vector<geometry::Pose> poses = smoothWindow(tracked, start, stop, options);
    const std::size_t keep_from = start == begin ? start : start + overlap / 2;
    const std::size_t keep_to = stop == end ? end : stop - (overlap - overlap / 2);
    for (std::size_t i = keep_from; i < keep_to; ++i) smoothed[i].T_wc = poses[i - start];
    if (stop == end) return;
    start = stop - overlap;
  }
}

double typicalInterval(const std::vector<core::StampedPose>& poses) {
  std::vector<double> intervals;
  intervals.reserve(poses.size());
  for (std::size_t i = 1; i < poses.size(); ++i) {
    intervals.push_back(poses[i].timestamp - poses[i - 1].timestamp);
  }
  const auto middle = intervals.begin() + static_cast<std::ptrdiff_t>(intervals.size() / 2);
  std::nth_element(intervals.begin(), middle, intervals.end());
  return *middle;
}

}  // namespace

core::Trajectory smoothTrajectory(const core::Trajectory& tracked,
                                  const TrajectorySmoothingOptions& options) {
  const std::vector<core::StampedPose>& poses = tracked.poses();
  if (poses.size() < 3) return tracked;
  std::vector<core::StampedPose> smoothed = poses;
  const double max_gap_s = options.max_gap_intervals * typicalInterval(poses);
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= poses.size(); ++i) {
    if (i < poses.size() && poses[i].timestamp - poses[i - 1].timestamp <= max_gap_s) continue;
    if (i - begin >= 3) smoothRun(poses, begin, i, options, smoothed);
    begin = i;
  }
  return core::Trajectory(std::move(smoothed));
}

}  // namespace segslam::optim
