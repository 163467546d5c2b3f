#pragma once

// Synthetic sequences several tests share (header-only, never linked into the library). Kept out
// of test_support.h, which tests include after cpp-httplib's header: that one brings <resolv.h>,
// whose `_res` macro breaks the Eigen headers that synth options pull in.

#include <fmt/format.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

#include "segslam/synth/generator.h"
#include "segslam/synth/synth_options.h"
#include "segslam/testing/synth_fingerprint.h"
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

// The sequence `options` describe, rendered once into SEGSLAM_TEST_SEQUENCE_CACHE (the source
// tree's .cache/test_sequences) under the renderer's fingerprint and kept there: the test
// processes of a run, and the plain and sanitizer builds' runs, read the same frames instead of
// each rendering them again. A sequence is rendered into a folder of its own and renamed into
// place, so that a process never sees one half written, whichever process renders it first.
// Never write into it; the cache can be deleted at any time.
inline std::filesystem::path sharedSequence(const synth::SynthOptions& options) {
  namespace fs = std::filesystem;
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  const std::string key = synth::toJson(options).dump();
  std::uint64_t hash = 14695981039346656037ULL;  // FNV-1a, stable across builds and runs
  for (const unsigned char c : key) hash = (hash ^ c) * 1099511628211ULL;
  const fs::path root = fs::path(SEGSLAM_TEST_SEQUENCE_CACHE) / SEGSLAM_SYNTH_FINGERPRINT;
  const fs::path folder = root / fmt::format("{:016x}", hash);
  if (fs::is_directory(folder)) return folder;
  const fs::path partial = root / fmt::format("{:016x}.{}.part", hash, ::getpid());
  fs::remove_all(partial);
  synth::generateSequence(options, partial);
  std::error_code taken;  // another process renamed its rendering into place first
  fs::rename(partial, folder, taken);
  if (taken) fs::remove_all(partial);
  return folder;
}

}  // namespace segslam::testing
