#pragma once

#include <fmt/os.h>

#include <cstddef>
#include <filesystem>
#include <vector>

#include "segslam/system/slam_system.h"

namespace segslam::system {

// A run's frame_log.csv (per-frame timings and state), a row written as each frame is tracked.
// What the run's summary needs of a frame stays in memory (16 bytes), not the frame's figures
// and pose (224 bytes): a session at 30 Hz holds 22 MB less an hour.
class FrameLog {
 public:
  // Opens `file` and writes the header; throws util::Error naming the file when it cannot.
  explicit FrameLog(const std::filesystem::path& file);

  void add(const FrameStats& stats);
  // Writes what is buffered and closes the file.
  void close();

  [[nodiscard]] const std::vector<double>& trackingMs() const { return tracking_ms_; }
  [[nodiscard]] const std::vector<double>& extractionMs() const { return extraction_ms_; }
  [[nodiscard]] std::size_t lostFrames() const { return lost_frames_; }

 private:
  fmt::ostream out_;
  std::vector<double> tracking_ms_;
  std::vector<double> extraction_ms_;
  std::size_t lost_frames_ = 0;
};

}  // namespace segslam::system
