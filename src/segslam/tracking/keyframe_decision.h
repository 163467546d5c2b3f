#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace segslam::tracking {

struct KeyFrameDecisionOptions {
  // A keyframe is forced after this many frames (one second at 30 Hz), so the map follows a
  // camera that moves slowly enough to stay above the tracked share.
  int max_frames_between_keyframes = 30;
  // New keyframe when the frame tracks less than this share of the reference keyframe's points
  // (of the most that a frame has tracked of them) ...
  double tracked_ratio = 0.75;
  // ... or when it tracks too few close (depth-trusted) points while this many close points are
  // new to the map.
  int min_close_points_tracked = 100;
  int min_close_points_untracked = 70;
  int min_inliers = 16;  // a keyframe needs a trustworthy pose
  // ... held by this many inliers on points a keyframe's own mask has checked (not
  // MapPoint::provisional), once the local map has any. A frame held mostly by provisional points
  // may be held by a person the late masks missed: its keyframe puts hundreds of new points on
  // him, and the next frames follow him (fr1_p2_s93_near_fast `--deterministic
  // --network-interval 12 --network-latency 12`: a keyframe on 15 checked of 70 matches as a
  // walker came to cover 45 % of the view, the camera then dragged 0.13 m in 8 frames and lost;
  // ATE 0.0140 -> 0.0054 m without that keyframe).
  int min_checked_inliers = 20;
};

// How much of the reference keyframe the frames still see: the reference's points that a frame
// tracks, against the most of them that any frame has tracked since that keyframe became the
// reference. Both sides count the same points (the keyframe's fresh ones included), so the share
// is at most 1, starts near 1 just after the keyframe and falls as the view moves on. The
// yardstick restarts with each new reference: an older keyframe that becomes the reference again
// may have lost points to culling and fusion since its best frame, and would otherwise ask for a
// keyframe on every frame.
class ReferenceOverlap {
 public:
  void update(std::uint64_t reference_keyframe_id, int tracked);
  [[nodiscard]] double share() const;
  [[nodiscard]] int tracked() const { return tracked_; }
  [[nodiscard]] int best() const { return best_; }

 private:
  std::optional<std::uint64_t> reference_id_;
  int tracked_ = 0;
  int best_ = 0;
};

// What the tracker knows about the current frame when it decides on a keyframe.
struct KeyFrameEvidence {
  int inliers = 0;
  int checked_inliers = 0;  // inliers on points that are not MapPoint::provisional
  // Whether the local map has such points: none before the first keyframe's own mask came.
  bool local_map_checked = false;
  double tracked_share = 1.0;  // ReferenceOverlap::share()
  int tracked_close = 0;       // close keypoints with a map point
  int untracked_close = 0;     // close keypoints without one
  std::uint64_t frames_since_keyframe = 0;
  bool mapping_idle = true;
  std::size_t queued_keyframes = 0;
};

bool needsKeyFrame(const KeyFrameEvidence& evidence, const KeyFrameDecisionOptions& options);

}  // namespace segslam::tracking
