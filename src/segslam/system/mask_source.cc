#include "segslam/system/mask_source.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <array>
#include <opencv2/imgproc.hpp>

#include "segslam/util/error.h"

namespace segslam::system {

namespace {

constexpr std::array<std::pair<MaskSource, const char*>, 5> kNames = {{
    {MaskSource::kNone, "none"},
    {MaskSource::kSemantic, "semantic"},
    {MaskSource::kGeometric, "geometric"},
    {MaskSource::kFused, "fused"},
    {MaskSource::kOracle, "oracle"},
}};

bool usesNetwork(MaskSource source) {
  return source == MaskSource::kSemantic || source == MaskSource::kFused;
}

}  // namespace

std::vector<std::string> maskSourceNames() {
  std::vector<std::string> names;
  for (const auto& [source, name] : kNames) names.emplace_back(name);
  return names;
}

MaskSource maskSourceFromName(const std::string& name) {
  for (const auto& [source, known] : kNames) {
    if (name == known) return source;
  }
  throw util::Error(fmt::format("unknown mask source '{}' (known: {})", name,
                                fmt::join(maskSourceNames(), ", ")));
}

std::string maskSourceName(MaskSource source) {
  for (const auto& [known, name] : kNames) {
    if (source == known) return name;
  }
  return "none";
}

namespace {

// The network `--seg auto` takes: the one named, else the config's; util::Error when the config's
// is not found.
std::string networkFound(const MaskSourceOptions& options,
                         const segmentation::ModelConfig& config) {
  if (options.model_file) {
    return fmt::format("segmentation network {} (named)", options.model_file->string());
  }
  const auto model = segmentation::resolveModelFile(config, options.model_config, std::nullopt);
  return fmt::format("segmentation network {}", model.lexically_normal().string());
}

}  // namespace

AutomaticMaskSource automaticMaskSource(const MaskSourceOptions& options) {
  const auto config = segmentation::readModelConfig(options.model_config);
  try {
    const std::string reason = networkFound(options, config);
    spdlog::info("masks: fused ({})", reason);
    return {MaskSource::kFused, reason};
  } catch (const util::Error& e) {
    // A warning, not a note: without the network a person who stands still is not masked, and a
    // build or checkout that cannot see its models gives far worse trajectories among people.
    spdlog::warn("masks: geometric only, the segmentation network is missing: {}", e.what());
    return {MaskSource::kGeometric, e.what()};
  }
}

namespace {

segmentation::Segment semanticSegment(const MaskSourceOptions& options,
                                      const segmentation::ModelConfig& config) {
  const auto model =
      segmentation::resolveModelFile(config, options.model_config, options.model_file);
  auto segmenter = std::make_shared<segmentation::SemanticSegmenter>(config, model);
  segmenter->warmUp();
  return [segmenter](const segmentation::SegmentationJob& job) {
    return segmenter->segment(job.current.bgr);
  };
}

segmentation::DepthFrame depthFrame(const segmentation::StreamFrame& frame) {
  segmentation::DepthFrame depth_frame{cv::Mat(), frame.depth};
  cv::cvtColor(frame.bgr, depth_frame.gray, cv::COLOR_BGR2GRAY);
  return depth_frame;
}

// The geometric segmenter's last output, as a prior for the next frame it compares.
struct LastMoving {
  std::uint64_t frame_id = 0;
  cv::Mat moving;
};

// An output this many frames older than the previous frame of a job still tells roughly where
// things moved: the thread of a threaded stream does not get every frame.
constexpr std::uint64_t kMaxMovingPriorAge = 3;

segmentation::Segment geometricSegment(const core::Camera& camera,
                                       const segmentation::GeometricOptions& options) {
  auto segmenter = std::make_shared<segmentation::GeometricSegmenter>(camera, options);
  auto last = std::make_shared<LastMoving>();
  return [segmenter, last](const segmentation::SegmentationJob& job) {
    if (job.previous.bgr.empty()) return segmentation::SemanticMasks{};
    segmentation::DepthFrame previous = depthFrame(job.previous);
    if (!last->moving.empty() && last->frame_id <= job.previous.id &&
        job.previous.id - last->frame_id <= kMaxMovingPriorAge) {
      previous.moving = last->moving;
    }
    cv::Mat dynamic = segmenter->segment(previous, depthFrame(job.current), job.known_dynamic);
    if (!dynamic.empty()) *last = {job.current.id, dynamic};
    return segmentation::SemanticMasks{dynamic, dynamic};
  };
}

// Geometric segmentation compares consecutive frames, so it runs on every frame it can.
constexpr int kGeometricInterval = 1;

segmentation::MaskStreamOptions streamOptions(bool synchronous, int interval, int latency,
                                              bool refine_fresh_masks, bool carry_labels) {
  segmentation::MaskStreamOptions options;
  options.carry_labels = carry_labels;
  options.synchronous = synchronous;
  options.interval = interval;
  options.latency_frames = latency;
  options.refine_fresh_masks = refine_fresh_masks;
  return options;
}

}  // namespace

namespace {

// Checked before anything loads, so that a run without masks fails at once.
const core::Camera& cameraOfDatasetWithMasks(const io::TumDataset& dataset, MaskSource source) {
  if (source == MaskSource::kOracle && !dataset.hasMasks()) {
    util::failAt(dataset.folder() / "mask.txt",
                 "oracle masks requested (--seg oracle) but the dataset has no mask.txt");
  }
  return dataset.camera();
}

// Masks are carried between frames by optical flow at half resolution, which OpenCV's DIS flow
// computes only on images with sides of at least 12 pixels.
constexpr int kSmallestMaskedImageSide = 32;

void requireFlowSize(const core::Camera& camera, MaskSource source) {
  if (camera.width < kSmallestMaskedImageSide || camera.height < kSmallestMaskedImageSide) {
    throw util::Error(fmt::format(
        "{} masks need images of at least {} x {} pixels (they are carried between frames by "
        "optical flow); the camera's are {} x {} (--seg none or oracle work on any size)",
        maskSourceName(source), kSmallestMaskedImageSide, kSmallestMaskedImageSide, camera.width,
        camera.height));
  }
}

}  // namespace

FrameMaskSource::FrameMaskSource(const io::TumDataset& dataset, const MaskSourceOptions& options,
                                 bool synchronous)
    : FrameMaskSource(cameraOfDatasetWithMasks(dataset, options.source), options, synchronous) {}

FrameMaskSource::FrameMaskSource(const core::Camera& camera, const MaskSourceOptions& options,
                                 bool synchronous)
    : source_(options.source) {
  if (usesNetwork(source_) || source_ == MaskSource::kGeometric) {
    requireFlowSize(camera, source_);
  }
  const auto flow = std::make_shared<segmentation::MaskPropagator>();
  if (usesNetwork(source_)) {
    const auto config = segmentation::readModelConfig(options.model_config);
    auto semantic_options = streamOptions(synchronous, options.network_interval,
                                          options.network_latency, true, options.carry_labels);
    semantic_options.border_linger_frames = options.border_linger_frames;
    semantic_ = std::make_unique<segmentation::MaskStream>(semanticSegment(options, config),
                                                           semantic_options, flow);
    semantic_classes_.emplace(config.classes);
  }
  if (source_ == MaskSource::kGeometric || source_ == MaskSource::kFused) {
    geometric_ = std::make_unique<segmentation::MaskStream>(
        geometricSegment(camera, options.geometric),
        streamOptions(synchronous, kGeometricInterval, 0, false, false), flow);
  }
}

FrameMasks FrameMaskSource::masks(const io::RgbdFrame& frame, std::size_t index) {
  FrameMasks masks{cv::Mat(), frame.labels, frame.instances, {}};
  if (source_ == MaskSource::kOracle) {
    masks.dynamic = frame.mask;
    return masks;
  }
  if (semantic_) {
    const segmentation::SemanticMasks network = semantic_->masksFor(index, frame.rgb, frame.depth);
    const cv::Mat labels =
        network.labels.empty() ? cv::Mat() : semantic_classes_->apply(network.labels);
    masks = {network.dynamic, labels, cv::Mat(), {}};
    for (auto& late : semantic_->takeLateOutputs()) {
      if (!late.labels.empty()) late.labels = semantic_classes_->apply(late.labels);
      masks.late.push_back(std::move(late));
    }
  }
  if (geometric_) {
    const cv::Mat moving =
        geometric_->masksFor(index, frame.rgb, frame.depth, masks.dynamic).dynamic;
    masks.dynamic = masks.dynamic.empty() ? moving : (masks.dynamic | moving);
    for (auto& late : geometric_->takeLateOutputs()) masks.late.push_back(std::move(late));
  }
  return masks;
}

std::vector<segmentation::LateOutput> FrameMaskSource::remainingLateOutputs() {
  std::vector<segmentation::LateOutput> remaining;
  if (semantic_) {
    for (auto& late : semantic_->takeRemainingOutputs()) {
      if (!late.labels.empty()) late.labels = semantic_classes_->apply(late.labels);
      remaining.push_back(std::move(late));
    }
  }
  if (geometric_) {
    for (auto& late : geometric_->takeRemainingOutputs()) remaining.push_back(std::move(late));
  }
  return remaining;
}

void FrameMaskSource::segmentKeyFrame(const io::RgbdFrame& frame, std::size_t index) {
  if (semantic_) semantic_->segmentKeyFrame(index, frame.rgb, frame.depth);
}

cv::Mat FrameMaskSource::dynamicMask(const io::RgbdFrame& frame, std::size_t index) {
  return masks(frame, index).dynamic;
}

void FrameMaskSource::setTrackingBusyShare(double share) {
  if (semantic_) semantic_->setTrackingBusyShare(share);
  if (geometric_) geometric_->setTrackingBusyShare(share);
}

int FrameMaskSource::networkRuns() const { return semantic_ ? semantic_->runs() : 0; }

double FrameMaskSource::meanNetworkMilliseconds() const {
  return semantic_ ? semantic_->meanRunMilliseconds() : 0.0;
}

}  // namespace segslam::system
