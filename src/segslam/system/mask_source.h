#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "segslam/io/tum_dataset.h"
#include "segslam/segmentation/geometric_segmenter.h"
#include "segslam/segmentation/mask_stream.h"
#include "segslam/segmentation/semantic_class_map.h"

namespace segslam::system {

// Where each frame's dynamic mask comes from.
enum class MaskSource {
  kNone,       // no masks: everything is treated as static
  kOracle,     // the dataset's ground-truth masks (mask.txt)
  kSemantic,   // a semantic segmentation network (asynchronous, carried by optical flow)
  kGeometric,  // whatever the camera motion does not explain (no model needed)
  kFused,      // semantic first, then geometric on the semantically static area; the union
};
std::vector<std::string> maskSourceNames();
MaskSource maskSourceFromName(const std::string& name);
std::string maskSourceName(MaskSource source);

struct MaskSourceOptions {
  MaskSource source = MaskSource::kNone;
  // Semantic masks: the network's model config and, optionally, the network file overriding it.
  std::filesystem::path model_config;
  std::optional<std::filesystem::path> model_file;
  segmentation::GeometricOptions geometric;
  // In synchronous (deterministic) mode the network runs on every this many frames; 1 scores the
  // network alone, without masks carried between its runs.
  int network_interval = 5;
  // In synchronous mode each network output is used this many frames after its frame, as on
  // its own thread: reproducible runs of the real-time pipeline.
  int network_latency = 0;
  // Whether the network's per-pixel labels are carried to every frame (the object map reads
  // them); without, FrameMasks::labels stays empty and carrying masks costs less.
  bool carry_labels = true;
  // See segmentation::MaskStreamOptions::border_linger_frames (the network's masks only).
  int border_linger_frames = 30;
};

// The masks used when none are asked for: fused when the segmentation network is found, else
// geometric, which needs no model. A network named in `options.model_file` is taken as found
// (loading it reports what is wrong with it); a broken model config is an error, not a fallback.
// The choice is logged, the fallback as a warning naming the places tried.
struct AutomaticMaskSource {
  MaskSource source = MaskSource::kGeometric;
  std::string reason;  // which network was found, or why none was
};
AutomaticMaskSource automaticMaskSource(const MaskSourceOptions& options);

// One frame's masks and the labels its map points get.
struct FrameMasks {
  cv::Mat dynamic;    // CV_8UC1, 255 = dynamic; empty = none
  cv::Mat labels;     // CV_8UC1 core::SemanticClass ids; empty = unknown
  cv::Mat instances;  // CV_16UC1 instance ids, 0 = none; empty = none
  // Segmenter outputs for earlier frames that arrived with this one (labels, when there are any,
  // as core::SemanticClass ids).
  std::vector<segmentation::LateOutput> late;
};

// Gives every frame of a sequence its dynamic mask (CV_8UC1, 255 = dynamic; empty = none) from
// the configured source. Frames must be asked for in order. Throws util::Error when the source
// cannot work (oracle without mask.txt, missing or broken network).
class FrameMaskSource {
 public:
  // synchronous: segment on the calling thread (reproducible) instead of segmentation threads.
  FrameMaskSource(const io::TumDataset& dataset, const MaskSourceOptions& options,
                  bool synchronous);
  // For frames that do not come from a dataset (a live camera, the Python module): oracle masks
  // are then each frame's RgbdFrame::mask, whatever the caller put there.
  FrameMaskSource(const core::Camera& camera, const MaskSourceOptions& options, bool synchronous);

  // With a network (semantic, fused) the labels are the network's, carried to this frame with
  // its mask and translated into core::SemanticClass ids, and there are no instances; otherwise
  // they are the dataset's (labels.txt, instances.txt), when it has them.
  FrameMasks masks(const io::RgbdFrame& frame, std::size_t index);
  cv::Mat dynamicMask(const io::RgbdFrame& frame, std::size_t index);
  // Asks the network (semantic, fused masks) for the own output of a frame handed on earlier,
  // ahead of other frames: it comes back in a later frame's FrameMasks::late with `keyframe` set.
  // Nothing for the other sources.
  void segmentKeyFrame(const io::RgbdFrame& frame, std::size_t index);
  // After the last frame: the outputs still on their way (keyframes' own masks among them).
  [[nodiscard]] std::vector<segmentation::LateOutput> remainingLateOutputs();
  // Whether segmentKeyFrame() delivers outputs (a network is in use).
  [[nodiscard]] bool segmentsKeyFrames() const { return semantic_ != nullptr; }

  // Whether masks are computed (semantic, geometric, fused) rather than read (oracle) or none.
  [[nodiscard]] bool segments() const { return semantic_ || geometric_; }
  // Tells the segmenters how busy the tracking thread is (segmentation::BusyShare), from any
  // thread: while tracking has no CPU to spare, they run less often.
  void setTrackingBusyShare(double share);

  [[nodiscard]] int networkRuns() const;
  [[nodiscard]] double meanNetworkMilliseconds() const;

 private:
  MaskSource source_;
  std::unique_ptr<segmentation::MaskStream> semantic_;
  std::optional<segmentation::SemanticClassMap> semantic_classes_;
  std::unique_ptr<segmentation::MaskStream> geometric_;
};

}  // namespace segslam::system
