#include "segslam/optim/trajectory_smoother.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace segslam::optim {
namespace {

constexpr double kFrameInterval = 1.0 / 30.0;

// A hand-held camera's path: a slow sway along x and y, turning slowly about its vertical axis.
geometry::Pose truePose(double t) {
  geometry::Pose T_wc = geometry::Pose::Identity();
  T_wc.translation() = Eigen::Vector3d(0.3 * std::sin(0.8 * t), 0.1 * std::sin(1.3 * t), 0.05 * t);
  T_wc.linear() = Eigen::AngleAxisd(0.3 * std::sin(0.5 * t), Eigen::Vector3d::UnitY()).matrix();
  return T_wc;
}

struct Tracked {
  core::Trajectory trajectory;
  std::vector<geometry::Pose> truth;
};

// `frames` frames from t = 0 (with `gap_after` frames missing after frame `gap_at`), each pose
// off the true one by `sigma_m` and `sigma_deg` per axis (Gaussian, fixed seed).
Tracked trackedPath(int frames, double sigma_m, double sigma_deg, int gap_at = -1,
                    int gap_frames = 0) {
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  Tracked tracked;
  for (int i = 0, k = 0; i < frames; ++i, ++k) {
    if (i == gap_at + 1) k += gap_frames;
    const double t = k * kFrameInterval;
    const geometry::Pose truth = truePose(t);
    geometry::Pose measured = truth;
    measured.translation() +=
        sigma_m * Eigen::Vector3d(noise(random), noise(random), noise(random));
    const Eigen::Vector3d rotation_error =
        sigma_deg * M_PI / 180.0 * Eigen::Vector3d(noise(random), noise(random), noise(random));
    measured.linear() =
        truth.linear() * Eigen::AngleAxisd(rotation_error.norm(), rotation_error.normalized());
    tracked.trajectory.append(t, measured);
    tracked.truth.push_back(truth);
  }
  return tracked;
}

double rmsPositionError(const core::Trajectory& trajectory,
                        const std::vector<geometry::Pose>& truth) {
  double sum = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    sum += (trajectory[i].T_wc.translation() - truth[i].translation()).squaredNorm();
  }
  return std::sqrt(sum / truth.size());
}

double rmsRotationErrorDeg(const core::Trajectory& trajectory,
                           const std::vector<geometry::Pose>& truth) {
  double sum = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::AngleAxisd error(truth[i].linear().transpose() * trajectory[i].T_wc.linear());
    sum += std::pow(error.angle() * 180.0 / M_PI, 2);
  }
  return std::sqrt(sum / truth.size());
}

TEST(TrajectorySmoother, TakesMuchOfTheFrameToFrameJitterOut) {
  const Tracked tracked = trackedPath(300, 0.004, 0.15);
  const core::Trajectory smoothed = smoothTrajectory(tracked.trajectory);
  ASSERT_EQ(smoothed.size(), tracked.trajectory.size());
  for (std::size_t i = 0; i < smoothed.size(); ++i) {
    EXPECT_EQ(smoothed[i].timestamp, tracked.trajectory[i].timestamp);
  }
  const double tracked_error = rmsPositionError(tracked.trajectory, tracked.truth);
  EXPECT_LT(rmsPositionError(smoothed, tracked.truth), 0.6 * tracked_error) << tracked_error;
  const double tracked_rotation_error = rmsRotationErrorDeg(tracked.trajectory, tracked.truth);
  EXPECT_LT(rmsRotationErrorDeg(smoothed, tracked.truth), 0.8 * tracked_rotation_error)
      << tracked_rotation_error;
}

TEST(TrajectorySmoother, KeepsATrajectoryWithoutJitterAsItIs) {
  const Tracked exact = trackedPath(150, 0.0, 0.0);
  const core::Trajectory smoothed = smoothTrajectory(exact.trajectory);
  EXPECT_LT(rmsPositionError(smoothed, exact.truth), 0.0005);
  EXPECT_LT(rmsRotationErrorDeg(smoothed, exact.truth), 0.02);
}

TEST(TrajectorySmoother, AWrongFrameDoesNotBendItsNeighbours) {
  Tracked tracked = trackedPath(90, 0.0, 0.0);
  std::vector<core::StampedPose> poses = tracked.trajectory.poses();
  poses[45].T_wc.translation() += Eigen::Vector3d(0.05, 0.0, 0.0);
  const core::Trajectory smoothed = smoothTrajectory(core::Trajectory(poses));
  EXPECT_LT((smoothed[45].T_wc.translation() - tracked.truth[45].translation()).norm(), 0.01);
  for (const int neighbour : {43, 44, 46, 47}) {
    EXPECT_LT(
        (smoothed[neighbour].T_wc.translation() - tracked.truth[neighbour].translation()).norm(),
        0.003)
        << neighbour;
  }
}

TEST(TrajectorySmoother, DoesNotTieFramesAcrossAGapInTracking) {
  // Frames lost for a second (tracking relocalised after it): the camera may have done anything
  // meanwhile, so a jump across the gap stays a jump.
  const Tracked tracked = trackedPath(120, 0.0, 0.0, 59, 30);
  std::vector<core::StampedPose> poses = tracked.trajectory.poses();
  for (std::size_t i = 60; i < poses.size(); ++i) {
    poses[i].T_wc.translation() += Eigen::Vector3d(0.0, 0.0, 0.5);
  }
  const core::Trajectory smoothed = smoothTrajectory(core::Trajectory(poses));
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_LT((smoothed[i].T_wc.translation() - poses[i].T_wc.translation()).norm(), 0.0005) << i;
  }
}

TEST(TrajectorySmoother, SolvesALongRunInWindowsAsInOne) {
  const Tracked tracked = trackedPath(1300, 0.004, 0.15);
  TrajectorySmoothingOptions whole;
  whole.max_window_frames = 100000;
  TrajectorySmoothingOptions windows;
  windows.max_window_frames = 400;
  const core::Trajectory in_one = smoothTrajectory(tracked.trajectory, whole);
  const core::Trajectory in_windows = smoothTrajectory(tracked.trajectory, windows);
  ASSERT_EQ(in_windows.size(), in_one.size());
  double largest_m = 0.0;
  double largest_deg = 0.0;
  for (std::size_t i = 0; i < in_one.size(); ++i) {
    largest_m = std::max(largest_m,
                         (in_windows[i].T_wc.translation() - in_one[i].T_wc.translation()).norm());
    const Eigen::AngleAxisd difference(in_one[i].T_wc.linear().transpose() *
                                       in_windows[i].T_wc.linear());
    largest_deg = std::max(largest_deg, difference.angle() * 180.0 / M_PI);
  }
  // Far below the noise taken out (4 mm, 0.15 deg): the solver's own tolerance.
  EXPECT_LT(largest_m, 1e-4);
  EXPECT_LT(largest_deg, 0.01);
  EXPECT_LT(rmsPositionError(in_windows, tracked.truth),
            0.6 * rmsPositionError(tracked.trajectory, tracked.truth));
}

TEST(TrajectorySmoother, LeavesTooShortTrajectoriesAsTheyAre) {
  const Tracked tracked = trackedPath(2, 0.01, 1.0);
  const core::Trajectory smoothed = smoothTrajectory(tracked.trajectory);
  ASSERT_EQ(smoothed.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(smoothed[i].T_wc.isApprox(tracked.trajectory[i].T_wc));
  }
  EXPECT_TRUE(smoothTrajectory(core::Trajectory()).empty());
}

}  // namespace
}  // namespace segslam::optim
