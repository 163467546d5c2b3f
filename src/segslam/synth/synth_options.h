#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "segslam/core/camera.h"

namespace segslam::synth {

// Everything that defines a synthetic sequence. Two runs with equal options produce byte-identical
// files, whatever the number of threads.
struct SynthOptions {
  int frames = 300;
  int width = 640;
  int height = 480;
  // Camera path: "xyz" (back-and-forth along the camera axes with small rotations, like TUM
  // fr1/xyz), "loop" (a closed path through the room that ends exactly at its start pose) or
  // "room" (a lap around the room's centre turning once all the way round, ending at its start
  // pose: the start's view comes back only at the end) or "static" (the camera does not move).
  std::string path = "xyz";
  // "loop" and "room": times round the same circuit; every lap but the first revisits what the
  // earlier ones mapped, so drift meets the loop early and the map is reused for a whole lap.
  int laps = 1;
  int people = 2;                // 0 = no people
  double person_speed = 1.0;     // walking speed in m/s; 0 = people stand still
  double person_size = 1.0;      // scale of a 1.75 m tall person
  bool moved_furniture = false;  // a chair is pushed across the floor during the sequence
  // "none": exact z quantised to 1/depth_factor; "kinect": axial noise growing with z and no depth
  // below 0.4 m, beyond 8 m and at depth discontinuities.
  std::string depth_noise = "none";
  std::uint32_t seed = 1;

  bool operator==(const SynthOptions&) const = default;
};

inline constexpr double kSynthFps = 30.0;
inline constexpr double kSynthDepthFactor = 5000.0;
inline constexpr double kSynthStartTimestamp = 1700000000.0;
inline constexpr int kSynthMaxPeople = 4;
inline constexpr double kSynthMaxPersonSpeed = 3.0;
inline constexpr double kSynthMinPersonSize = 0.5;
inline constexpr double kSynthMaxPersonSize = 1.4;
inline constexpr int kSynthMinWidth = 32;
inline constexpr int kSynthMinHeight = 24;
inline constexpr int kSynthMaxWidth = 4096;
inline constexpr int kSynthMaxHeight = 4096;
inline constexpr int kSynthMaxFrames = 100000;
// The loop is one lap of fixed size; fewer frames would make the camera faster than a handheld one.
inline constexpr int kSynthMinLoopFrames = 240;  // per lap
inline constexpr int kSynthMaxLaps = 10;

std::vector<std::string> cameraPathNames();
std::vector<std::string> depthNoiseNames();

// Throws util::Error with a one-line message naming the offending option (as on the command line,
// e.g. "--frames must be at least 1, got 0") when the options cannot make a sequence.
void validateOptions(const SynthOptions& options);

// The pinhole camera of a synthetic sequence: fx = fy = 525 * width / 640, principal point at the
// image centre, no distortion, depth factor 5000, 30 fps.
core::Camera synthCamera(const SynthOptions& options);

// Every option by name, as meta.json records them: equal options give equal JSON.
nlohmann::json toJson(const SynthOptions& options);

// Timestamp of frame k in seconds: kSynthStartTimestamp + k / fps.
double frameTimestamp(int frame);

}  // namespace segslam::synth
