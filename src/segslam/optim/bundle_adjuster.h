#pragma once

#include <Eigen/Core>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/optim/rgbd_observation.h"

namespace segslam::optim {

// The ids are the caller's, carried through untouched so that it can map results back.
struct BaKeyFrame {
  std::uint64_t id = 0;
  geometry::Pose T_cw = geometry::Pose::Identity();  // world-to-camera
  bool fixed = false;                                // held constant, e.g. to fix the gauge
};

struct BaPoint {
  std::uint64_t id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world frame
};

struct BaObservation {
  std::size_t keyframe = 0;  // index into BundleAdjustmentProblem::keyframes
  std::size_t point = 0;     // index into BundleAdjustmentProblem::points
  RgbdObservation observation;
};

struct BundleAdjustmentProblem {
  StereoIntrinsics intrinsics;
  std::vector<BaKeyFrame> keyframes;
  std::vector<BaPoint> points;
  std::vector<BaObservation> observations;
};

struct BundleAdjustmentOptions {
  int iterations_first = 5;     // robust stage, all observations
  int iterations_second = 10;   // plain least squares on the first stage's inliers
  bool remove_outliers = true;  // false: skip the second stage
  int num_threads = 1;          // 1 keeps results bit-for-bit reproducible
  // Set from another thread, it stops the solver after its current iteration (the result is then
  // partial; the caller discards it).
  const std::atomic<bool>* cancel = nullptr;
};

struct BundleAdjustmentResult {
  std::vector<bool> observation_inlier;  // per observation, at the final estimate
  int iterations = 0;                    // solver iterations of both stages
  double initial_cost = 0.0;  // first stage's cost before optimising: 1/2 sum of Huber(chi2)
  double final_cost = 0.0;    // last stage's cost after optimising (without the robust kernel
                              // and the outliers if the second stage ran)
};

// Bundle adjustment in two stages: Levenberg-Marquardt with Huber kernels (width sqrt of the
// chi2 threshold) on every observation whose point starts in front of its camera; then, if
// `remove_outliers`, again without the kernel on the observations that passed the chi2 test.
// Non-fixed keyframe poses and all point positions are updated in place. Every observation is
// finally labelled at the final estimate (chi2 test and point in front), so the caller can erase
// the outliers from its map. At least one keyframe should be fixed; otherwise the solution is
// determined only up to a rigid motion. Throws std::invalid_argument on out-of-range indices.
BundleAdjustmentResult bundleAdjust(BundleAdjustmentProblem& problem,
                                    const BundleAdjustmentOptions& options = {});

}  // namespace segslam::optim
