#include "segslam/synth/synth_options.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "segslam/util/error.h"

namespace segslam::synth {

namespace {

[[noreturn]] void fail(const std::string& message) { throw util::Error(message); }

void requireInRange(const char* option, int value, int low, int high) {
  if (value < low || value > high) {
    fail(fmt::format("{} must be between {} and {}, got {}", option, low, high, value));
  }
}

void requireInRange(const char* option, double value, double low, double high) {
  if (!std::isfinite(value) || value < low || value > high) {
    fail(fmt::format("{} must be between {} and {}, got {}", option, low, high, value));
  }
}

void requireMember(const char* option, const std::string& value,
                   const std::vector<std::string>& names) {
  if (std::find(names.begin(), names.end(), value) == names.end()) {
    fail(fmt::format("{} must be one of {}, got '{}'", option, fmt::join(names, ", "), value));
  }
}

}  // namespace

std::vector<std::string> cameraPathNames() { return {"xyz", "loop", "room", "static"}; }

std::vector<std::string> depthNoiseNames() { return {"none", "kinect"}; }

void validateOptions(const SynthOptions& options) {
  requireInRange("--frames", options.frames, 1, kSynthMaxFrames);
  requireInRange("--width", options.width, kSynthMinWidth, kSynthMaxWidth);
  requireInRange("--height", options.height, kSynthMinHeight, kSynthMaxHeight);
  requireMember("--path", options.path, cameraPathNames());
  requireMember("--depth-noise", options.depth_noise, depthNoiseNames());
  requireInRange("--people", options.people, 0, kSynthMaxPeople);
  requireInRange("--person-speed", options.person_speed, 0.0, kSynthMaxPersonSpeed);
  requireInRange("--person-size", options.person_size, kSynthMinPersonSize, kSynthMaxPersonSize);
  requireInRange("--laps", options.laps, 1, kSynthMaxLaps);
  const int min_frames = kSynthMinLoopFrames * options.laps;
  if ((options.path == "loop" || options.path == "room") && options.frames < min_frames) {
    fail(fmt::format("--path {} needs at least {} frames ({} per lap at handheld speed), got {}",
                     options.path, min_frames, kSynthMinLoopFrames, options.frames));
  }
}

core::Camera synthCamera(const SynthOptions& options) {
  core::Camera camera;
  camera.name = "segslam_synth";
  camera.width = options.width;
  camera.height = options.height;
  camera.fx = 525.0 * options.width / 640.0;
  camera.fy = camera.fx;
  camera.cx = (options.width - 1) / 2.0;
  camera.cy = (options.height - 1) / 2.0;
  camera.depth_factor = kSynthDepthFactor;
  camera.fps = kSynthFps;
  return camera;
}

nlohmann::json toJson(const SynthOptions& options) {
  return {{"frames", options.frames},
          {"width", options.width},
          {"height", options.height},
          {"path", options.path},
          {"laps", options.laps},
          {"people", options.people},
          {"person_speed", options.person_speed},
          {"person_size", options.person_size},
          {"moved_furniture", options.moved_furniture},
          {"depth_noise", options.depth_noise},
          {"seed", options.seed}};
}

double frameTimestamp(int frame) { return kSynthStartTimestamp + frame / kSynthFps; }

}  // namespace segslam::synth
