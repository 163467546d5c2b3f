#include "segslam/tracking/keyframe_decision.h"

#include <algorithm>

namespace segslam::tracking {

void ReferenceOverlap::update(std::uint64_t reference_keyframe_id, int tracked) {
  if (reference_keyframe_id != reference_id_) {
    reference_id_ = reference_keyframe_id;
    best_ = 0;
  }
  tracked_ = tracked;
  best_ = std::max(best_, tracked);
}

double ReferenceOverlap::share() const {
  return best_ > 0 ? static_cast<double>(tracked_) / best_ : 1.0;
}

bool needsKeyFrame(const KeyFrameEvidence& evidence, const KeyFrameDecisionOptions& options) {
  if (evidence.inliers < options.min_inliers) return false;
  if (evidence.local_map_checked && evidence.checked_inliers < options.min_checked_inliers) {
    return false;
  }
  // A queue of keyframes would only be mapped late; a short one is fine for RGB-D.
  const bool can_queue = evidence.mapping_idle || evidence.queued_keyframes < 3;
  if (evidence.frames_since_keyframe >=
      static_cast<std::uint64_t>(options.max_frames_between_keyframes)) {
    return can_queue;
  }
  const bool need_close = evidence.tracked_close < options.min_close_points_tracked &&
                          evidence.untracked_close > options.min_close_points_untracked;
  const bool below_ratio = evidence.tracked_share < options.tracked_ratio || need_close;
  // While the mapper is busy only a frame that is losing the map asks for a keyframe.
  const bool weak = evidence.tracked_share < 0.25 || need_close;
  return below_ratio && (evidence.mapping_idle || weak) && can_queue;
}

}  // namespace segslam::tracking
