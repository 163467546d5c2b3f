#pragma once

// Synthetic sequences several tests share (header-only, never linked into the library). Kept out
// of test_support.h, which tests include after cpp-httplib's header: that one brings <resolv.h>,
// whose `_res` macro breaks the Eigen headers that synth options pull in.

#include <filesystem>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "segslam/synth/generator.h"
#include "segslam/synth/synth_options.h"
#include "segslam/testing/test_support.h"

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

// The sequence `options` describe, rendered once per test process into a folder removed when the
// process ends: tests that only read the same frames share them instead of rendering them again
// (a whole-sequence suite runs in one process, see cmake/GTestSuites.cmake). Never write into it.
inline std::filesystem::path sharedSequence(const synth::SynthOptions& options) {
  static std::mutex mutex;
  static std::vector<std::pair<synth::SynthOptions, std::unique_ptr<ScopedTempDir>>> rendered;
  const std::lock_guard lock(mutex);
  for (const auto& [rendered_options, dir] : rendered) {
    if (rendered_options == options) return dir->path() / "sequence";
  }
  auto dir = std::make_unique<ScopedTempDir>();
  synth::generateSequence(options, dir->path() / "sequence");
  rendered.emplace_back(options, std::move(dir));
  return rendered.back().second->path() / "sequence";
}

}  // namespace segslam::testing
