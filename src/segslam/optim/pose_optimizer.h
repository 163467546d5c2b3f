#pragma once

#include <Eigen/Core>
#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/optim/rgbd_observation.h"

namespace segslam::optim {

// A map point (world frame) seen by the frame whose pose is optimised.
struct PoseObservation {
  Eigen::Vector3d point_w;
  RgbdObservation observation;
};

struct PoseOptimizationOptions {
  int rounds = 4;                 // at least 1: the inlier labels come from the end of a round
  int iterations_per_round = 10;  // Levenberg-Marquardt iterations, rejected steps included
};

struct PoseOptimizationResult {
  geometry::Pose T_cw;
  std::vector<bool> inlier;  // per observation, from the final pose
  int num_inliers = 0;
};

// Motion-only bundle adjustment: refines the world-to-camera pose of one frame against fixed map
// points. Each round runs Levenberg-Marquardt on the observations that were inliers after the
// previous round (in the first, all whose point is in front), then re-labels every observation
// by its chi2 at the new pose, so an outlier can come back. All rounds but the last use a Huber
// kernel of width sqrt(chi2 threshold); the last, run on inliers only, uses plain least squares.
// Points behind the camera are outliers. A round with fewer than 3 observations to use leaves the
// pose as it is.
[[nodiscard]] PoseOptimizationResult optimizePose(const StereoIntrinsics& intrinsics,
                                                  const geometry::Pose& initial_T_cw,
                                                  const std::vector<PoseObservation>& observations,
                                                  const PoseOptimizationOptions& options = {});

}  // namespace segslam::optim
