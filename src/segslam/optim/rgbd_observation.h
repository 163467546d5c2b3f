#pragma once

#include <Eigen/Core>

namespace segslam::optim {

// Pinhole intrinsics plus the "virtual stereo" baseline of ORB-SLAM2's RGB-D mode: a keypoint at
// column u with depth z gets a virtual right-image column u_r = u - bf / z, so depth enters the
// optimisation as a third reprojection coordinate with pixel units.
struct StereoIntrinsics {
  double fx = 525.0;
  double fy = 525.0;
  double cx = 319.5;
  double cy = 239.5;
  double bf = 40.0;  // fx * baseline (pixels * metres)
};

// A keypoint that observes a 3D point. `right_u < 0` means no depth: a plain 2D observation.
// `information` is 1 / sigma^2 of the keypoint's pyramid level (sigma = scale_factor^level).
struct RgbdObservation {
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // undistorted keypoint
  double right_u = -1.0;
  double information = 1.0;

  [[nodiscard]] bool hasDepth() const { return right_u >= 0.0; }
};

// Chi-square thresholds at 95 % for 2 and 3 degrees of freedom, used both as Huber widths
// (their square roots) and to label outliers.
inline constexpr double kChi2Mono = 5.991;
inline constexpr double kChi2Stereo = 7.815;

// The outlier threshold that fits the observation's degrees of freedom.
[[nodiscard]] inline double chi2Threshold(const RgbdObservation& observation) {
  return observation.hasDepth() ? kChi2Stereo : kChi2Mono;
}

}  // namespace segslam::optim
