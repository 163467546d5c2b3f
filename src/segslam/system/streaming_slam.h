#pragma once

#include <cstdint>
#include <optional>

#include "segslam/core/camera.h"
#include "segslam/core/trajectory.h"
#include "segslam/dense/dense_map.h"
#include "segslam/dense/map_builder.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/segmentation/busy_share.h"
#include "segslam/system/map_keyframe_feed.h"
#include "segslam/system/mask_source.h"
#include "segslam/system/slam_system.h"

namespace segslam::system {

struct StreamingSlamOptions {
  SlamOptions slam;
  MaskSourceOptions masks;
  // Dense map of the keyframes (denseMap()); its mask dilation is the SLAM one.
  bool build_map = true;
  dense::MapBuilderOptions map;
  // With a segmentation network, local mapping waits at most this many frames for each
  // keyframe's own network output (SlamOptions::mapper.own_mask_wait_frames).
  int keyframe_mask_wait_frames = 20;
  // Seeds OpenCV's random generator of the constructing thread, as `segslam run --seed` does.
  std::uint64_t seed = 0;
};

// What the pipeline made of one frame.
struct StreamedFrame {
  FrameStats stats;  // stats.T_wc is the frame's pose
  FrameMasks masks;  // the dynamic mask SLAM used (the caller's included) and the labels
};

// The pipeline of `segslam run` (runSequence) for frames the caller hands over one at a time,
// from a live camera or another program: the same masks, SLAM, late and keyframe masks and dense
// map, in the same order, so that a deterministic run of a dataset's frames gives runSequence's
// trajectory exactly.
class StreamingSlam {
 public:
  // Throws util::Error when the mask source cannot work (a missing or broken network).
  StreamingSlam(const core::Camera& camera, const StreamingSlamOptions& options);
  StreamingSlam(const StreamingSlam&) = delete;
  StreamingSlam& operator=(const StreamingSlam&) = delete;

  // frame.rgb: CV_8UC3 BGR; frame.depth: CV_32FC1 metres; both of the camera's size, fresh
  // images per frame (they are shared, not copied). frame.mask: the caller's own dynamic mask
  // (CV_8UC1, non-zero = dynamic; empty = none), the only one with MaskSource::kOracle and added
  // to the source's otherwise. Timestamps must increase. Throws util::Error after finish().
  StreamedFrame track(const io::RgbdFrame& frame);
  // Waits for local mapping, loop closing and the map's keyframes; tracking ends here.
  void finish();
  [[nodiscard]] bool finished() const { return finished_; }

  // Every tracked frame at its final pose; call finish() first for the final poses.
  [[nodiscard]] core::Trajectory cameraTrajectory() const { return slam_.cameraTrajectory(); }
  [[nodiscard]] core::Trajectory keyFrameTrajectory() const { return slam_.keyFrameTrajectory(); }
  [[nodiscard]] std::size_t numKeyFrames() const { return slam_.numKeyFrames(); }
  [[nodiscard]] std::size_t numMapPoints() const { return slam_.numMapPoints(); }
  [[nodiscard]] loop::LoopClosingStats loopClosingStats() const { return slam_.loopClosingStats(); }
  [[nodiscard]] int networkRuns() const { return masks_.networkRuns(); }

  // The dense map at the keyframes' final poses (finishes the run first). Throws util::Error
  // when the options did not ask for a map.
  [[nodiscard]] dense::DenseMap denseMap();

 private:
  [[nodiscard]] FrameMasks masksFor(const io::RgbdFrame& frame, std::uint64_t frame_id);
  void handOverLateMasks(const FrameMasks& masks);

  MaskSource mask_source_;
  FrameMaskSource masks_;
  SlamSystem slam_;
  std::optional<dense::MapBuilder> map_builder_;
  std::optional<MapKeyFrameFeed> map_feed_;
  segmentation::BusyShare tracking_load_;
  std::uint64_t next_frame_id_ = 0;
  bool finished_ = false;
};

}  // namespace segslam::system
