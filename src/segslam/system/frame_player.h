#pragma once

#include <chrono>
#include <cstddef>
#include <optional>

#include "segslam/io/tum_dataset.h"
#include "segslam/segmentation/busy_share.h"
#include "segslam/system/mask_source.h"

namespace segslam::system {

struct PlayedFrame {
  io::RgbdFrame frame;
  FrameMasks masks;
  double mask_ms = 0.0;  // the tracking thread's time on the masks, or waiting for them
  double lag_ms = 0.0;   // realtime: how late the frame was taken after its arrival (0 if early)
};

struct FramePlayerOptions {
  io::FrameLayers layers;
  // Frames no earlier than a camera would deliver them (the dataset's timestamps, from the first
  // frame on) instead of as fast as they load.
  bool realtime = false;
  // Played as fast as frames load, computed masks are made on a worker thread while the
  // calling thread loads the next frame: carrying masks (optical flow, depth snapping) then
  // costs the tracking thread nothing, and does not take the second core from its feature
  // extraction either. Off: masks are made on the calling thread (reproducible runs).
  bool load_ahead = true;
};

// Hands a sequence's frames with their masks to the tracking thread, in order, and tells the
// segmenters how busy that thread is: a thread that never waits for a frame has no CPU to spare.
class FramePlayer {
 public:
  FramePlayer(const io::TumDataset& dataset, FrameMaskSource& masks, FramePlayerOptions options);
  FramePlayer(const FramePlayer&) = delete;
  FramePlayer& operator=(const FramePlayer&) = delete;

  // Frame `index` (0, 1, ... in order, each once) and its masks; `last` is the index of the last
  // frame that will be asked for.
  PlayedFrame take(std::size_t index, std::size_t last);

 private:
  [[nodiscard]] io::RgbdFrame load(std::size_t index);
  [[nodiscard]] double waitForArrival(double timestamp);
  // The frame's masks, with the calling thread's time on them in `played.mask_ms`.
  [[nodiscard]] FrameMasks timedMasks(PlayedFrame& played, std::size_t index);
  [[nodiscard]] FrameMasks masksWhileLoadingNext(PlayedFrame& played, std::size_t index,
                                                 std::size_t last);

  const io::TumDataset& dataset_;
  FrameMaskSource& masks_;
  FramePlayerOptions options_;
  segmentation::BusyShare tracking_load_;
  std::optional<io::RgbdFrame> next_;  // loaded ahead
  std::optional<double> first_timestamp_;
  std::chrono::steady_clock::time_point first_arrival_;
};

}  // namespace segslam::system
