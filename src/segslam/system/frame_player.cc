#include "segslam/system/frame_player.h"

#include <future>
#include <thread>

#include "segslam/io/frame_images.h"
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
  LoadedFrame loaded = next_ ? std::move(*next_) : load(index);
  next_.reset();
  if (loaded.damage) {
    played.damage = std::move(loaded.damage);
    return played;
  }
  played.frame = std::move(loaded.frame);
  played.frame_id = next_frame_id_++;
  if (options_.realtime) played.lag_ms = waitForArrival(played.frame.timestamp);
  // Since the last frame's masks: tracking it, loading this one and waiting for its arrival.
  tracking_load_.sample(util::thisThreadCpuSeconds(), wallSeconds());
  masks_.setTrackingBusyShare(tracking_load_.value());
  played.masks =
      options_.load_ahead ? masksWhileLoadingNext(played, index, last) : timedMasks(played);
  // Waiting for masks is not time the tracking thread could have given the segmenters.
  tracking_load_.restart(util::thisThreadCpuSeconds(), wallSeconds());
  return played;
}

FrameMasks FramePlayer::timedMasks(PlayedFrame& played) {
  const auto start = std::chrono::steady_clock::now();
  FrameMasks masks = masks_.masks(played.frame, played.frame_id);
  played.mask_ms = util::millisecondsSince(start);
  return masks;
}

FrameMasks FramePlayer::masksWhileLoadingNext(PlayedFrame& played, std::size_t index,
                                              std::size_t last) {
  auto masks =
      std::async(std::launch::async, [&] { return masks_.masks(played.frame, played.frame_id); });
  if (index < last) next_ = load(index + 1);
  const auto start = std::chrono::steady_clock::now();
  FrameMasks ready = masks.get();
  played.mask_ms = util::millisecondsSince(start);  // loading is not the masks' time
  return ready;
}

FramePlayer::LoadedFrame FramePlayer::load(std::size_t index) {
  try {
    return {dataset_.loadFrame(index, options_.layers), std::nullopt};
  } catch (const io::DamagedImageError& e) {
    return {{}, e.what()};
  }
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
