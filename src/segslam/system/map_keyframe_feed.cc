#include "segslam/system/map_keyframe_feed.h"

namespace segslam::system {

MapKeyFrameFeed::MapKeyFrameFeed(dense::MapBuilder& builder, bool wait_for_own_masks,
                                 std::uint64_t max_wait_frames)
    : builder_(builder),
      wait_for_own_masks_(wait_for_own_masks),
      max_wait_frames_(max_wait_frames) {}

void MapKeyFrameFeed::addKeyFrame(std::uint64_t frame_id, double timestamp,
                                  dense::KeyFrameImages images) {
  if (!wait_for_own_masks_) {
    builder_.addKeyFrame(frame_id, timestamp, std::move(images));
    return;
  }
  held_[frame_id] = Held{timestamp, std::move(images)};
}

void MapKeyFrameFeed::addOwnMask(const segmentation::LateOutput& output) {
  const auto held = held_.find(output.frame_id);
  if (held == held_.end()) return;
  dense::KeyFrameImages& images = held->second.images;
  if (!output.dynamic.empty()) {
    images.dynamic_mask =
        images.dynamic_mask.empty() ? output.dynamic : (images.dynamic_mask | output.dynamic);
  }
  if (!output.labels.empty()) images.labels = output.labels;
  builder_.addKeyFrame(held->first, held->second.timestamp, std::move(images));
  held_.erase(held);
}

void MapKeyFrameFeed::setTrackedFrame(std::uint64_t frame_id) {
  while (!held_.empty() && held_.begin()->first + max_wait_frames_ <= frame_id) {
    auto& [id, held] = *held_.begin();
    builder_.addKeyFrame(id, held.timestamp, std::move(held.images));
    held_.erase(held_.begin());
  }
}

void MapKeyFrameFeed::flush() { setTrackedFrame(UINT64_MAX - max_wait_frames_); }

}  // namespace segslam::system
