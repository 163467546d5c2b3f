#include "segslam/system/streaming_slam.h"

#include <chrono>
#include <opencv2/core/utility.hpp>

#include "segslam/util/elapsed_time.h"
#include "segslam/util/error.h"
#include "segslam/util/thread_priority.h"

namespace segslam::system {

namespace {

// runSequence seeds OpenCV before anything is made, so this does too, first of all.
MaskSourceOptions seededMaskOptions(const StreamingSlamOptions& options) {
  cv::setRNGSeed(static_cast<int>(options.seed));
  MaskSourceOptions masks = options.masks;
  masks.carry_labels = options.build_map;  // only the dense map reads labels
  return masks;
}

SlamOptions slamOptions(const StreamingSlamOptions& options, const FrameMaskSource& masks) {
  SlamOptions slam = options.slam;
  if (masks.segmentsKeyFrames()) {
    slam.mapper.own_mask_wait_frames = options.keyframe_mask_wait_frames;
  }
  return slam;
}

double steadyClockSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

StreamingSlam::StreamingSlam(const core::Camera& camera, const StreamingSlamOptions& options)
    : mask_source_(options.masks.source),
      masks_(camera, seededMaskOptions(options), options.slam.deterministic),
      slam_(camera, slamOptions(options, masks_)) {
  if (!options.build_map) return;
  dense::MapBuilderOptions map_options = options.map;
  map_options.keyframe.mask_dilation_px = options.slam.mask_dilation_px;
  map_builder_.emplace(camera, map_options);
  map_feed_.emplace(*map_builder_, masks_.segmentsKeyFrames());
}

StreamedFrame StreamingSlam::track(const io::RgbdFrame& frame) {
  if (finished_) throw util::Error("the run is finished: no frame can be tracked after finish()");
  const std::uint64_t frame_id = next_frame_id_++;
  const auto start = std::chrono::steady_clock::now();
  StreamedFrame streamed;
  streamed.masks = masksFor(frame, frame_id);
  const double mask_ms = util::millisecondsSince(start);
  handOverLateMasks(streamed.masks);
  FrameStats& stats = streamed.stats;
  stats = slam_.processFrame(frame.timestamp, frame.rgb, frame.depth, streamed.masks.dynamic);
  stats.mask_ms = mask_ms;
  stats.tracking_ms += mask_ms;
  if (stats.keyframe) {
    masks_.segmentKeyFrame(frame, frame_id);
    if (map_feed_) {
      const FrameMasks& masks = streamed.masks;
      map_feed_->addKeyFrame(
          stats.frame_id, frame.timestamp,
          {frame.rgb, frame.depth, masks.dynamic, masks.labels, masks.instances});
      map_builder_->setLiveKeyFrames(slam_.keyFrameTrajectory());
    }
  }
  if (map_feed_) map_feed_->setTrackedFrame(stats.frame_id);
  return streamed;
}

FrameMasks StreamingSlam::masksFor(const io::RgbdFrame& frame, std::uint64_t frame_id) {
  // As FramePlayer does: the segmenters slow down while the calling thread has no CPU to spare.
  tracking_load_.sample(util::thisThreadCpuSeconds(), steadyClockSeconds());
  masks_.setTrackingBusyShare(tracking_load_.value());
  FrameMasks masks = masks_.masks(frame, frame_id);
  tracking_load_.restart(util::thisThreadCpuSeconds(), steadyClockSeconds());
  if (frame.mask.empty()) return masks;
  const cv::Mat callers_mask = frame.mask != 0;  // 255 = dynamic, as the sources give
  if (mask_source_ == MaskSource::kOracle || masks.dynamic.empty()) {
    masks.dynamic = callers_mask;
  } else {
    masks.dynamic = masks.dynamic | callers_mask;
  }
  return masks;
}

void StreamingSlam::handOverLateMasks(const FrameMasks& masks) {
  for (const auto& late : masks.late) {
    if (late.keyframe) {
      slam_.addKeyFrameMask(late.frame_id, late.dynamic);
      if (map_feed_) map_feed_->addOwnMask(late);
    } else {
      slam_.applyLateMask(late.frame_id, late.dynamic, late.depth);
    }
  }
}

void StreamingSlam::finish() {
  if (finished_) return;
  finished_ = true;
  if (map_feed_) map_feed_->flush();
  slam_.finish();
}

dense::DenseMap StreamingSlam::denseMap() {
  if (!map_builder_) {
    throw util::Error("no dense map: the pipeline was made without one (build_map off)");
  }
  finish();
  return map_builder_->build(slam_.keyFrameTrajectory());
}

}  // namespace segslam::system
