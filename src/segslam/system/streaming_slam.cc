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

double steadyClockSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

StreamingSlam::StreamingSlam(const core::Camera& camera, const StreamingSlamOptions& options)
    : mask_source_(options.masks.source),
      masks_(camera, seededMaskOptions(options), options.slam.deterministic),
      pipeline_(camera, masks_, options) {}

StreamedFrame StreamingSlam::track(const io::RgbdFrame& frame) {
  if (finished()) throw util::Error("the run is finished: no frame can be tracked after finish()");
  const std::uint64_t frame_id = next_frame_id_++;
  const auto start = std::chrono::steady_clock::now();
  StreamedFrame streamed;
  streamed.masks = masksFor(frame, frame_id);
  streamed.stats = pipeline_.track(frame, streamed.masks, frame_id, util::millisecondsSince(start));
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

dense::DenseMap StreamingSlam::denseMap() {
  if (pipeline_.mapBuilder() == nullptr) {
    throw util::Error("no dense map: the pipeline was made without one (build_map off)");
  }
  finish();
  return pipeline_.mapBuilder()->build(slam().keyFrameTrajectory());
}

}  // namespace segslam::system
