#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/core/trajectory.h"
#include "segslam/feature/orb_extractor.h"
#include "segslam/loop/bow_loop_detector.h"
#include "segslam/loop/cnn_loop_detector.h"
#include "segslam/loop/descriptor_vote_detector.h"
#include "segslam/loop/loop_closer.h"
#include "segslam/map/frame.h"
#include "segslam/map/map.h"
#include "segslam/map/map_snapshot.h"
#include "segslam/mapping/local_mapper.h"
#include "segslam/optim/trajectory_smoother.h"
#include "segslam/tracking/tracker.h"

namespace segslam::system {

struct SlamOptions {
  feature::OrbExtractorOptions orb;
  tracking::TrackerOptions tracker;
  mapping::LocalMapperOptions mapper;
  // Loop closing on its own thread (inline in deterministic mode). Candidates by a CNN
  // descriptor with the union mask (loop::CnnLoopDetector) when a backbone is given, else by bag
  // of words of each keyframe's static area (loop::BowLoopDetector) when a vocabulary is given,
  // else by loop::DescriptorVoteDetector, which needs neither.
  bool loop_closing = true;
  loop::LoopClosingOptions loop;
  std::optional<loop::CnnLoopBackbone> loop_backbone;
  loop::CnnLoopOptions loop_cnn;
  std::shared_ptr<const place::Vocabulary> loop_vocabulary;
  loop::BowLoopOptions loop_bow;
  loop::DescriptorVoteOptions loop_detector;
  // Relocalisation candidates by bag of words (tracking::KeyFrameDatabase); without a
  // vocabulary a lost frame is matched against the most recent keyframes only.
  std::shared_ptr<const place::Vocabulary> relocalisation_vocabulary;
  // Virtual stereo baseline in metres and the depth, in baselines, below which a keypoint's
  // depth is trusted to create points (40 baselines ~ 3.1 m).
  double virtual_baseline_m = map::kDefaultVirtualBaselineM;
  double close_depth_baselines = 40.0;
  // Dilation (pixels) of the dynamic mask before keypoint extraction and point projection.
  int mask_dilation_px = 10;
  // Runs local mapping on the calling thread after each keyframe: slower, but every run with the
  // same input gives the same result.
  bool deterministic = false;
  // cameraTrajectory() smoothed under a camera moving at near-constant velocity; none: the
  // tracked poses as they are.
  std::optional<optim::TrajectorySmoothingOptions> trajectory_smoothing =
      optim::TrajectorySmoothingOptions{};
};

// Per-frame figures for the run log.
struct FrameStats {
  std::uint64_t frame_id = 0;
  double timestamp = 0.0;
  double extraction_ms = 0.0;
  double mask_ms = 0.0;      // obtaining the dynamic mask on the tracking thread (not the network)
  double tracking_ms = 0.0;  // mask and extraction included: what a frame costs the tracking thread
  int keypoints = 0;
  int matches = 0;
  tracking::TrackingState state = tracking::TrackingState::kNotInitialised;
  bool keyframe = false;
  // Live keyframes and map points after the frame: what a long session's memory follows.
  std::size_t live_keyframes = 0;
  std::size_t live_map_points = 0;
  // The pose tracking gave the frame (camera-to-world), before local mapping and loop closing
  // refine the map: what a live caller acts on. None when the frame is not tracked.
  std::optional<geometry::Pose> T_wc;
};

// The SLAM pipeline: ORB extraction on the static area, tracking on the calling thread, local
// mapping on its own thread (or inline in deterministic mode).
class SlamSystem {
 public:
  SlamSystem(const core::Camera& camera, SlamOptions options);
  ~SlamSystem();
  SlamSystem(const SlamSystem&) = delete;
  SlamSystem& operator=(const SlamSystem&) = delete;

  // bgr: CV_8UC3. depth_m: CV_32F metres. dynamic_mask: empty or CV_8U, non-zero = dynamic.
  // With the CNN loop detector, keyframes share bgr (not copied) until it is described: hand a
  // fresh image per frame.
  FrameStats processFrame(double timestamp, const cv::Mat& bgr, const cv::Mat& depth_m,
                          const cv::Mat& dynamic_mask);
  // A dynamic mask for an earlier frame (frame_id as processFrame numbered it), arrived late:
  // map points on what it marks are culled. Returns how many.
  int applyLateMask(std::uint64_t frame_id, const cv::Mat& dynamic_mask, const cv::Mat& depth_m);
  // The own dynamic mask (CV_8UC1, non-zero = dynamic, not dilated) of the keyframe made from
  // frame `frame_id`, which local mapping waits for (SlamOptions::mapper.own_mask_wait_frames):
  // the keyframe's points on what it marks are culled before they are mapped.
  void addKeyFrameMask(std::uint64_t frame_id, const cv::Mat& dynamic_mask);
  // Waits for local mapping to finish its queue; call before reading the trajectories.
  void finish();

  // The sensor a map file records for this system's camera and settings.
  [[nodiscard]] map::MapFileSensor mapSensor() const;
  // Continues in a saved map (before the first frame): its keyframes become relocalisation and
  // loop candidates, tracking starts lost and relocalises into the map; keyframes and points
  // made later extend it (or, with tracker.localize_only, none are made).
  void restoreMap(const map::MapFileContents& contents);
  // The map as the map file holds it, identity left to the caller; call after finish().
  [[nodiscard]] map::MapFileContents captureMap() const;
  // Restored map points that are still in the map (all of them before the first frame).
  [[nodiscard]] std::size_t restoredPointsLeft() const;
  [[nodiscard]] const map::MapSessions& sessions() const { return sessions_; }

  // Every tracked frame, placed relative to its reference keyframe's final pose.
  [[nodiscard]] core::Trajectory trackedCameraTrajectory() const;
  // The tracked trajectory smoothed (SlamOptions::trajectory_smoothing); the tracked one without.
  [[nodiscard]] core::Trajectory cameraTrajectory() const;
  // This session's keyframes (not those of a restored map: their images are not this run's).
  [[nodiscard]] core::Trajectory keyFrameTrajectory() const;
  [[nodiscard]] std::size_t numKeyFrames() const;
  [[nodiscard]] std::size_t numMapPoints() const;
  [[nodiscard]] double bundleAdjustmentSeconds() const {
    return mapper_.totalBundleAdjustmentSeconds();
  }
  // Empty when loop closing is off.
  [[nodiscard]] loop::LoopClosingStats loopClosingStats() const;
  [[nodiscard]] mapping::OwnMaskStats ownMaskStats() const { return mapper_.ownMaskStats(); }
  // The rolling-shutter readout tracking estimated (tracking::ReadoutEstimator); empty for a
  // global-shutter camera.
  [[nodiscard]] std::optional<double> rollingShutterReadout() const;

 private:
  // Deterministic mode: local mapping and loop closing of what is queued, on this thread.
  void mapInline();

  SlamOptions options_;
  std::shared_ptr<const map::FrameCamera> camera_;
  feature::OrbExtractor extractor_;
  map::Map map_;
  mapping::LocalMapper mapper_;
  std::unique_ptr<loop::LoopCloser> loop_closer_;
  tracking::Tracker tracker_;
  map::MapSessions sessions_;
  // Loop detectors' descriptions of the restored keyframes, as the file held them.
  std::map<std::uint64_t, std::string> restored_descriptions_;
  std::uint64_t next_frame_id_ = 0;
};

}  // namespace segslam::system
