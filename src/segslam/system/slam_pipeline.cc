#include "segslam/system/slam_pipeline.h"

#include "segslam/util/error.h"

namespace segslam::system {

namespace {

SlamOptions slamOptions(const SlamPipelineOptions& options, const FrameMaskSource& masks) {
  SlamOptions slam = options.slam;
  if (masks.segmentsKeyFrames()) {
    slam.mapper.own_mask_wait_frames = options.keyframe_mask_wait_frames;
  }
  slam.tracker.localize_only = options.map_file.localize_only;
  if (options.map_file.localize_only) slam.loop_closing = false;
  return slam;
}

}  // namespace

SlamPipeline::SlamPipeline(const core::Camera& camera, FrameMaskSource& masks,
                           const SlamPipelineOptions& options)
    : masks_(masks), options_(options), slam_(camera, slamOptions(options, masks)) {
  if (options.map_file.load) {
    loaded_ = loadMapInto(slam_, *options.map_file.load,
                          runIdentity(options.map_file, options.dense_map_folder));
  }
  if (!options.build_map) return;
  dense::MapBuilderOptions map_options = options.map;
  map_options.keyframe.mask_dilation_px = options.slam.mask_dilation_px;
  map_options.synchronous = options.slam.deterministic;
  map_builder_.emplace(camera, map_options);
  map_feed_.emplace(*map_builder_, masks.segmentsKeyFrames());
  if (!loaded_) return;
  if (auto earlier = linkedDenseMap(*loaded_, *options.map_file.load)) {
    map_builder_->setEarlierMap(std::move(*earlier));
  }
}

FrameStats SlamPipeline::track(const io::RgbdFrame& frame, const FrameMasks& masks,
                               std::uint64_t mask_frame_id, double mask_ms) {
  if (finished_) throw util::Error("the run is finished: no frame can be tracked after it");
  handOverLateOutputs(masks.late);
  FrameStats stats = slam_.processFrame(frame.timestamp, frame.rgb, frame.depth, masks.dynamic);
  stats.mask_ms = mask_ms;
  stats.tracking_ms += mask_ms;
  if (stats.keyframe) {
    masks_.segmentKeyFrame(frame, mask_frame_id);
    if (map_feed_) {
      map_feed_->addKeyFrame(
          stats.frame_id, frame.timestamp,
          {frame.rgb, frame.depth, masks.dynamic, masks.labels, masks.instances});
      map_builder_->setLiveKeyFrames(slam_.keyFrameTrajectory());
    }
  }
  if (map_feed_) map_feed_->setTrackedFrame(stats.frame_id);
  return stats;
}

// A keyframe's own mask goes to local mapping and the dense map, another frame's to the map
// points it shows on a moving object.
void SlamPipeline::handOverLateOutputs(const std::vector<segmentation::LateOutput>& outputs) {
  for (const auto& late : outputs) {
    if (late.keyframe) {
      slam_.addKeyFrameMask(late.frame_id, late.dynamic);
      if (map_feed_) map_feed_->addOwnMask(late);
    } else {
      points_culled_by_late_masks_ += slam_.applyLateMask(late.frame_id, late.dynamic, late.depth);
    }
  }
}

void SlamPipeline::finish() {
  if (finished_) return;
  finished_ = true;
  handOverLateOutputs(masks_.remainingLateOutputs());
  if (map_feed_) map_feed_->flush();
  slam_.finish();
}

std::uintmax_t SlamPipeline::saveMap(const std::filesystem::path& file) {
  finish();
  return saveMapOf(slam_, file, runIdentity(options_.map_file, options_.dense_map_folder),
                   loaded_ ? &*loaded_ : nullptr);
}

}  // namespace segslam::system
