#pragma once

#include "segslam/core/trajectory.h"

namespace segslam::optim {

// The noise model of smoothTrajectory. Tracking places each frame on its own matches, so its
// pose jitters by millimetres from frame to frame (across the view, where a small rotation and a
// small translation explain the image alike) while the camera itself, a body of some mass,
// changes its velocity smoothly: at 30 Hz the jitter is most of the frames' error
// (bench/results/trajectory_smoothing.md).
struct TrajectorySmoothingOptions {
  // How far a tracked frame's position and orientation may lie from the camera's (1 sigma).
  double position_sigma_m = 0.003;
  double rotation_sigma_deg = 0.1;
  // How fast the camera's velocity and angular velocity change (1 sigma): a hand-held camera or
  // a robot's, not a thrown one.
  double acceleration_m_s2 = 2.0;
  double angular_acceleration_rad_s2 = 4.0;
  // Tracked frames beyond this many of the trajectory's typical frame intervals apart (frames
  // lost between them) are not tied: the camera may have moved anyhow meanwhile.
  double max_gap_intervals = 3.0;
  // A long run is solved in windows of this many frames, each overlapping the next by
  // `window_overlap_frames` and keeping its half of the overlap: a frame's smoothed pose depends
  // on its neighbours within a few frames only, while one problem over an hour's frames would
  // take gigabytes.
  int max_window_frames = 1800;
  int window_overlap_frames = 60;
  // A frame farther than this many sigmas from where its neighbours place it (a wrong pose)
  // pulls only linearly (Huber), so it does not bend the frames around it.
  double robust_sigmas = 2.0;
};

// Fixed-interval smoothing of a tracked camera trajectory: the poses that best fit both the
// tracked ones (each a measurement with the noise above) and a camera moving at constant velocity
// up to random accelerations, solved over each run of frames without a gap. Same timestamps;
// runs of fewer than 3 frames are returned as they are.
[[nodiscard]] core::Trajectory smoothTrajectory(const core::Trajectory& tracked,
                                                const TrajectorySmoothingOptions& options = {});

}  // namespace segslam::optim
