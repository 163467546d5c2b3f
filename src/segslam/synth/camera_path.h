#pragma once

#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/synth/synth_options.h"

namespace segslam::synth {

// Camera-to-world poses (camera x right, y down, z forward) of every frame for options.path,
// at handheld speeds (at most 0.4 m/s and 30 deg/s), always inside the room and looking at
// its furniture mostly 0.8-4.5 m away:
// - "xyz": the camera stands near x = 0.95 m looking at the table and the far wall and moves back
//   and forth along its x, then y, then z axis (up to 15 cm, one back-and-forth per 4 s), turning
//   slightly (a few degrees) all the time, like TUM fr1/xyz;
// - "loop": one lap of a 0.45 m radius circle at about 1.4 m height, turning from the far wall
//   to the left wall (70 degrees) and back; the last pose equals the first exactly;
// - "static": the xyz path's start pose for every frame.
std::vector<geometry::Pose> cameraTrajectory(const SynthOptions& options);

}  // namespace segslam::synth
