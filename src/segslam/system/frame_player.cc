#include "segslam/system/frame_player.h"

#include <future>
#include <thread>

#include "segslam/util/elapsed_time.h"
#include "segslam/util/thread_priority.h"

namespace segslam::system {

namespace {

double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

FramePlayer::FramePlayer(const io::TumDataset& dataset, FrameMaskSource& masks,
                         FramePlayerOptions options)
    : dataset_(dataset), masks_(masks), options_(options) {
  options_.load_ahead = options_.load_ahead && !options_.realtime && masks_.segments();
}

PlayedFrame FramePlayer::take(std::size_t index, std::size_t last) {
  PlayedFrame played;
  played.frame = next_ ? std::move(*next_) : load(index);
  next_.reset();
  if (options_.realtime) played.lag_ms = waitForArrival(played.frame.timestamp);
  // Since the last frame's masks: tracking it, loading this one and waiting for its arrival.
  tracking_load_.sample(util::thisThreadCpuSeconds(), wallSeconds());
  masks_.setTrackingBusyShare(tracking_load_.value());
  played.masks =
      options_.load_ahead ? masksWhileLoadingNext(played, index, last) : timedMasks(played, index);
  // Waiting for masks is not time the tracking thread could have given the segmenters.
  tracking_load_.restart(util::thisThreadCpuSeconds(), wallSeconds());
  return played;
}

FrameMasks FramePlayer::timedMasks(PlayedFrame& played, std::size_t index) {
  const auto start = std::chrono::steady_clock::now();
  FrameMasks masks = masks_.masks(played.frame, index);
  played.mask_ms = util::millisecondsSince(start);
  return masks;
}

FrameMasks FramePlayer::masksWhileLoadingNext(PlayedFrame& played, std::size_t index,
                                              std::size_t last) {
  auto masks = std::async(std::launch::async, [&] { return masks_.masks(played.frame, index); });
  if (index < last) next_ = load(index + 1);
  const auto start = std::chrono::steady_clock::now();
  FrameMasks ready = masks.get();
  played.mask_ms = util::millisecondsSince(start);  // loading is not the masks' time
  return ready;
}

io::RgbdFrame FramePlayer::load(std::size_t index) {
  return dataset_.loadFrame(index, options_.layers);
}

double FramePlayer::waitForArrival(double timestamp) {
  const auto now = std::chrono::steady_clock::now();
  if (!first_timestamp_) {
    first_timestamp_ = timestamp;
    first_arrival_ = now;
    return 0.0;
  }
  const auto arrival =
      first_arrival_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(timestamp - *first_timestamp_));
  if (now < arrival) {
    std::this_thread::sleep_until(arrival);
    return 0.0;
  }
  return std::chrono::duration<double, std::milli>(now - arrival).count();
}

}  // namespace segslam::system
