#pragma once

// Synthetic sequences several tests share (header-only, never linked into the library). Kept out
// of test_support.h, which tests include after cpp-httplib's header: that one brings <resolv.h>,
// whose `_res` macro breaks the Eigen headers that synth options pull in.

#include "segslam/synth/synth_options.h"

namespace segslam::testing {

// A lap around the synthetic room without people, small (320x240) and with Kinect-like depth
// noise: the odometry drifts along it, and its end shows its start again (loop closing,
// relocalisation).
inline synth::SynthOptions noisyRoomLap(int frames) {
  synth::SynthOptions lap;
  lap.path = "room";
  lap.people = 0;
  lap.frames = frames;
  lap.width = 320;
  lap.height = 240;
  lap.depth_noise = "kinect";
  return lap;
}

}  // namespace segslam::testing
