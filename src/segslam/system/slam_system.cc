#include "segslam/system/slam_system.h"

#include <chrono>
#include <opencv2/imgproc.hpp>

#include "segslam/feature/static_mask.h"
#include "segslam/util/elapsed_time.h"

namespace segslam::system {

namespace {

geometry::Pose resolvedPose(const tracking::Tracker::FramePoseRecord& record) {
  // A culled reference keyframe is replaced by its parent, composing the frozen relative pose.
  geometry::Pose T_c_reference = record.T_c_reference();
  const map::KeyFrame* reference = record.reference;
  while (reference->bad && reference->parent != nullptr) {
    T_c_reference = T_c_reference * reference->T_c_parent;
    reference = reference->parent;
  }
  return T_c_reference * reference->T_cw;
}

// The system dilates the mask once and shares it between extraction and point projection.
// Levels are extracted in parallel: the second core is mostly idle between local BAs, and the
// keypoints are the same either way.
feature::OrbExtractorOptions extractorOptions(feature::OrbExtractorOptions options) {
  options.mask_dilation_px = 0;
  options.parallel_levels = true;
  return options;
}

std::unique_ptr<loop::LoopCandidateDetector> loopCandidateDetector(const SlamOptions& options) {
  if (options.loop_backbone) {
    return std::make_unique<loop::CnnLoopDetector>(*options.loop_backbone, options.loop_cnn);
  }
  if (options.loop_vocabulary) {
    return std::make_unique<loop::BowLoopDetector>(options.loop_vocabulary, options.loop_bow);
  }
  return std::make_unique<loop::DescriptorVoteDetector>(options.loop_detector);
}

}  // namespace

SlamSystem::SlamSystem(const core::Camera& camera, SlamOptions options)
    : options_(options),
      camera_(std::make_shared<map::FrameCamera>(
          camera, options.virtual_baseline_m, options.close_depth_baselines,
          feature::ScaleLevels(options.orb.num_levels, options.orb.scale_factor))),
      extractor_(extractorOptions(options.orb)),
      mapper_(map_, options.mapper),
      tracker_(map_, mapper_, options.tracker, options.relocalisation_vocabulary) {
  if (options_.loop_closing) {
    loop_closer_ = std::make_unique<loop::LoopCloser>(
        map_, mapper_, loopCandidateDetector(options_), options_.loop);
    mapper_.setProcessedKeyFrameObserver([this](std::shared_ptr<map::KeyFrame> keyframe) {
      loop_closer_->insertKeyFrame(keyframe);
    });
  } else {
    // Local mapping is then the keyframes' last stage: it frees what culled keyframes held.
    mapper_.setProcessedKeyFrameObserver([this](std::shared_ptr<map::KeyFrame> keyframe) {
      std::lock_guard lock(map_.mutex);
      map_.releaseCulledKeyFrames(keyframe->id);
    });
  }
  if (!options_.deterministic) {
    mapper_.start();
    if (loop_closer_) loop_closer_->start();
  }
}

SlamSystem::~SlamSystem() { finish(); }

FrameStats SlamSystem::processFrame(double timestamp, const cv::Mat& bgr, const cv::Mat& depth_m,
                                    const cv::Mat& dynamic_mask) {
  const auto start = std::chrono::steady_clock::now();
  FrameStats stats;
  stats.frame_id = next_frame_id_++;
  stats.timestamp = timestamp;
  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  // The camera looks for the map through the mask when the mask loses it. A network output
  // carried on after the people it marked had left can cover the scene's texture until the next
  // output comes (people9 of bench/soak.sh, two walkers near the camera: 17 frames lost at once);
  // a frame that cannot be tracked outside the mask is tried again on the whole image, and a lost
  // camera's frames are taken whole at once. A person's keypoints hardly give a pose: tracking
  // searches the map's static points, and relocalisation places a frame only on enough of them
  // that keyframes' own masks verified, within reach of the last pose.
  const bool lost = tracker_.state() == tracking::TrackingState::kLost;
  const cv::Mat mask =
      lost ? cv::Mat() : feature::dilateDynamicMask(dynamic_mask, options_.mask_dilation_px);
  auto frameOutside = [&](const cv::Mat& frame_mask) {
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
    extractor_.extract(gray, frame_mask, keypoints, descriptors);
    stats.keypoints = static_cast<int>(keypoints.size());
    map::Frame frame(stats.frame_id, timestamp, std::move(keypoints), std::move(descriptors),
                     depth_m, frame_mask, camera_);
    // Shared, not copied: the caller hands a fresh image per frame.
    if (loop_closer_ && options_.loop_backbone) frame.image = bgr;
    return frame;
  };
  map::Frame frame = frameOutside(mask);
  stats.extraction_ms = util::millisecondsSince(start);
  {
    std::lock_guard lock(map_.mutex);
    const auto result = mask.empty()
                            ? tracker_.track(std::move(frame))
                            : tracker_.track(std::move(frame), [&] { return frameOutside({}); });
    stats.state = result.state;
    stats.matches = result.matches;
    stats.keyframe = result.new_keyframe;
    stats.live_keyframes = map_.numKeyFrames();
    stats.live_map_points = map_.numMapPoints();
    if (result.state == tracking::TrackingState::kOk) {
      stats.T_wc = tracker_.currentFrame().T_cw.inverse();
    }
  }
  mapper_.setTrackedFrame(stats.frame_id);
  if (options_.deterministic) mapInline();
  stats.tracking_ms = util::millisecondsSince(start);
  return stats;
}

void SlamSystem::mapInline() {
  mapper_.processQueued();
  if (loop_closer_) loop_closer_->processQueued();
}

void SlamSystem::addKeyFrameMask(std::uint64_t frame_id, const cv::Mat& dynamic_mask) {
  mapper_.addKeyFrameMask(frame_id,
                          feature::dilateDynamicMask(dynamic_mask, options_.mask_dilation_px));
  if (options_.deterministic) mapInline();
}

int SlamSystem::applyLateMask(std::uint64_t frame_id, const cv::Mat& dynamic_mask,
                              const cv::Mat& depth_m) {
  std::lock_guard lock(map_.mutex);
  return tracker_.cullPointsOnLateMask(frame_id, dynamic_mask, depth_m);
}

void SlamSystem::finish() {
  mapper_.finish();
  mapper_.processQueued();
  if (loop_closer_) loop_closer_->finish();
}

map::MapFileSensor SlamSystem::mapSensor() const {
  return {camera_->camera, options_.virtual_baseline_m, options_.close_depth_baselines,
          options_.orb.num_levels, options_.orb.scale_factor};
}

void SlamSystem::restoreMap(const map::MapFileContents& contents) {
  std::lock_guard lock(map_.mutex);
  sessions_ = map::restoreMap(contents, camera_, map_);
  for (const auto& saved : contents.keyframes) {
    if (!saved.place_description.empty()) {
      restored_descriptions_[saved.id] = saved.place_description;
    }
  }
  if (loop_closer_) {
    for (const auto& keyframe : map_.keyFrames()) {
      const auto description = restored_descriptions_.find(keyframe->id);
      loop_closer_->addRestoredKeyFrame(*keyframe, description == restored_descriptions_.end()
                                                       ? std::string()
                                                       : description->second);
    }
  }
  tracker_.startInRestoredMap();
}

map::MapFileContents SlamSystem::captureMap() const {
  std::lock_guard lock(map_.mutex);
  map::MapFileContents contents = map::captureMap(map_, sessions_);
  for (auto& saved : contents.keyframes) {
    if (loop_closer_) saved.place_description = loop_closer_->savedDescription(saved.id);
    const auto restored = restored_descriptions_.find(saved.id);
    // A loaded keyframe keeps what the file said of it when this run's detector has nothing
    // of it (another detector, or no loop closing).
    if (saved.place_description.empty() && restored != restored_descriptions_.end()) {
      saved.place_description = restored->second;
    }
  }
  return contents;
}

std::size_t SlamSystem::restoredPointsLeft() const {
  std::lock_guard lock(map_.mutex);
  std::size_t left = 0;
  for (const auto& point : map_.mapPoints()) left += sessions_.points.count(point->id);
  return left;
}

loop::LoopClosingStats SlamSystem::loopClosingStats() const {
  return loop_closer_ ? loop_closer_->stats() : loop::LoopClosingStats{};
}

core::Trajectory SlamSystem::cameraTrajectory() const {
  core::Trajectory tracked = trackedCameraTrajectory();
  if (!options_.trajectory_smoothing) return tracked;
  return optim::smoothTrajectory(tracked, *options_.trajectory_smoothing);
}

core::Trajectory SlamSystem::trackedCameraTrajectory() const {
  std::lock_guard lock(map_.mutex);
  core::Trajectory trajectory;
  for (const auto& record : tracker_.frameRecords()) {
    trajectory.append(record.timestamp, resolvedPose(record).inverse());
  }
  return trajectory;
}

core::Trajectory SlamSystem::keyFrameTrajectory() const {
  std::lock_guard lock(map_.mutex);
  core::Trajectory trajectory;
  for (const auto& keyframe : map_.keyFrames()) {
    if (sessions_.keyframes.count(keyframe->id) > 0) continue;  // restored: an earlier session's
    trajectory.append(keyframe->timestamp, keyframe->T_cw.inverse());
  }
  return trajectory;
}

std::optional<double> SlamSystem::rollingShutterReadout() const {
  std::lock_guard lock(map_.mutex);
  return tracker_.rollingShutterReadout();
}

std::size_t SlamSystem::numKeyFrames() const {
  std::lock_guard lock(map_.mutex);
  return map_.numKeyFrames();
}

std::size_t SlamSystem::numMapPoints() const {
  std::lock_guard lock(map_.mutex);
  return map_.numMapPoints();
}

}  // namespace segslam::system
