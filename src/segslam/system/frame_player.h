#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

#include "segslam/io/tum_dataset.h"
#include "segslam/segmentation/busy_share.h"
#include "segslam/system/mask_source.h"

namespace segslam::system {

struct PlayedFrame {
  // Set when an image of the frame is damaged (io::DamagedImageError's message): the frame is to
  // be skipped, and `frame` and `masks` are empty; it never reached the mask source.
  std::optional<std::string> damage;
  io::RgbdFrame frame;
  FrameMasks masks;
  // The frame's number among the frames handed on, damaged ones not counted: the frame id SLAM
  // gives it, and the index its masks were made for (FrameMaskSource::masks).
  std::size_t frame_id = 0;
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
  // frame that will be asked for. A frame with a damaged image comes back with `damage` set.
  PlayedFrame take(std::size_t index, std::size_t last);

 private:
  struct LoadedFrame {
    io::RgbdFrame frame;
    std::optional<std::string> damage;
  };

  [[nodiscard]] LoadedFrame load(std::size_t index);
  [[nodiscard]] double waitForArrival(double timestamp);
  // The frame's masks, with the calling thread's time on them in `played.mask_ms`.
  [[nodiscard]] FrameMasks timedMasks(PlayedFrame& played);
  [[nodiscard]] FrameMasks masksWhileLoadingNext(PlayedFrame& played, std::size_t index,
                                                 std::size_t last);

  const io::TumDataset& dataset_;
  FrameMaskSource& masks_;
  FramePlayerOptions options_;
  segmentation::BusyShare tracking_load_;
  std::optional<LoadedFrame> next_;  // loaded ahead
  std::size_t next_frame_id_ = 0;
  std::optional<double> first_timestamp_;
  std::chrono::steady_clock::time_point first_arrival_;
};

}  // namespace segslam::system
