#pragma once

#include "segslam/map/frame.h"

namespace segslam::tracking {

struct ReadoutEstimatorOptions {
  // Weight of each frame's evidence one frame later: the estimate follows a change (frames
  // played backwards read their last row first) within about 1 / (1 - forgetting) frames.
  double forgetting = 0.95;
  // Weight of the camera's configured readout against the frames' evidence (1 / s^2, the unit of
  // ReadoutEvidence::information): about that of one frame turning at 5 deg/s, so that the
  // configured value holds while the camera is still and the frames tell nothing.
  double prior_information = 5.0e4;
};

// One frame's evidence on the readout, from its inlier residuals r_i after its pose was optimised
// with the keypoints compensated for `readout_s`, and the keypoints' readout gradients g_i
// (map::Frame::readout_gradient): residual_along_gradient = sum w_i g_i . r_i, information =
// sum w_i |g_i|^2, where r_i = projection - keypoint and w_i the keypoint's inverse variance
// (1 / px^2). The frame's readout is readout_s + residual_along_gradient / information.
struct ReadoutEvidence {
  double readout_s = 0.0;
  double residual_along_gradient = 0.0;
  double information = 0.0;
};

// The evidence of a frame compensated for `readout_s` and placed: its inliers on map points that
// an own mask has checked (not provisional: a person the masks missed moves on his own).
ReadoutEvidence readoutEvidence(const map::Frame& frame, double readout_s);

// The rolling-shutter readout (seconds from the first row to the last), estimated from the
// tracked frames: each frame's Gauss-Newton step from the readout it was compensated with, the
// steps averaged by their information with forgetting, around the camera's configured value.
// The configured value may be wrong in size (another sensor) or in sign: frames played backwards
// (or by a camera mounted upside down) have their last row read first. A global-shutter camera
// (0) is not estimated.
class ReadoutEstimator {
 public:
  ReadoutEstimator(double configured_s, double max_abs_s, ReadoutEstimatorOptions options = {});

  void addFrame(const ReadoutEvidence& evidence);
  // Within +-max_abs_s.
  [[nodiscard]] double readout() const { return readout_; }

 private:
  ReadoutEstimatorOptions options_;
  double configured_s_ = 0.0;
  double max_abs_s_ = 0.0;
  double information_ = 0.0;  // the frames', forgotten
  double weighted_sum_ = 0.0;
  double readout_ = 0.0;
};

}  // namespace segslam::tracking
