#pragma once

#include <cstdint>
#include <optional>

#include "segslam/core/camera.h"
#include "segslam/core/trajectory.h"
#include "segslam/dense/dense_map.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/segmentation/busy_share.h"
#include "segslam/system/mask_source.h"
#include "segslam/system/slam_pipeline.h"

namespace segslam::system {

struct StreamingSlamOptions : SlamPipelineOptions {
  MaskSourceOptions masks;
  // Seeds OpenCV's random generator of the constructing thread, as `segslam run --seed` does.
  std::uint64_t seed = 0;
};

// What the pipeline made of one frame.
struct StreamedFrame {
  FrameStats stats;  // stats.T_wc is the frame's pose
  FrameMasks masks;  // the dynamic mask SLAM used (the caller's included) and the labels
};

// The pipeline of `segslam run` (runSequence) for frames the caller hands over one at a time,
// from a live camera or another program: the same masks and the same SlamPipeline, so that a
// deterministic run of a dataset's frames gives runSequence's trajectory exactly.
class StreamingSlam {
 public:
  // Throws util::Error when the mask source cannot work (a missing or broken network) or the
  // map file to load cannot be loaded.
  StreamingSlam(const core::Camera& camera, const StreamingSlamOptions& options);
  StreamingSlam(const StreamingSlam&) = delete;
  StreamingSlam& operator=(const StreamingSlam&) = delete;

  // frame.rgb: CV_8UC3 BGR; frame.depth: CV_32FC1 metres; both of the camera's size, fresh
  // images per frame (they are shared, not copied). frame.mask: the caller's own dynamic mask
  // (CV_8UC1, non-zero = dynamic; empty = none), the only one with MaskSource::kOracle and added
  // to the source's otherwise. Timestamps must increase. Throws util::Error after finish().
  StreamedFrame track(const io::RgbdFrame& frame);
  // Waits for the network, local mapping, loop closing and the map's keyframes; tracking ends
  // here.
  void finish() { pipeline_.finish(); }
  [[nodiscard]] bool finished() const { return pipeline_.finished(); }
  // Writes the SLAM map for a later `segslam run --load-map` or StreamingSlam (finishes the run
  // first); returns the file's size.
  std::uintmax_t saveMap(const std::filesystem::path& file) { return pipeline_.saveMap(file); }

  // Every tracked frame at its final pose, smoothed as SlamOptions::trajectory_smoothing says
  // (the tracked poses: trackedCameraTrajectory); call finish() first for the final poses.
  [[nodiscard]] core::Trajectory cameraTrajectory() const { return slam().cameraTrajectory(); }
  [[nodiscard]] core::Trajectory trackedCameraTrajectory() const {
    return slam().trackedCameraTrajectory();
  }
  [[nodiscard]] core::Trajectory keyFrameTrajectory() const { return slam().keyFrameTrajectory(); }
  [[nodiscard]] std::size_t numKeyFrames() const { return slam().numKeyFrames(); }
  [[nodiscard]] std::size_t numMapPoints() const { return slam().numMapPoints(); }
  [[nodiscard]] loop::LoopClosingStats loopClosingStats() const {
    return slam().loopClosingStats();
  }
  [[nodiscard]] int networkRuns() const { return masks_.networkRuns(); }
  // The loaded map's keyframes and points (none without one) and its points still in the map.
  [[nodiscard]] const std::optional<LoadedMap>& loadedMap() const { return pipeline_.loadedMap(); }
  [[nodiscard]] std::size_t loadedPointsLeft() const { return slam().restoredPointsLeft(); }

  // The dense map at the keyframes' final poses (finishes the run first). Throws util::Error
  // when the options did not ask for a map.
  [[nodiscard]] dense::DenseMap denseMap();

 private:
  [[nodiscard]] const SlamSystem& slam() const { return pipeline_.slam(); }
  [[nodiscard]] FrameMasks masksFor(const io::RgbdFrame& frame, std::uint64_t frame_id);

  MaskSource mask_source_;
  FrameMaskSource masks_;
  SlamPipeline pipeline_;
  segmentation::BusyShare tracking_load_;
  std::uint64_t next_frame_id_ = 0;
};

}  // namespace segslam::system
