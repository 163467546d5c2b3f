#include "segslam/system/mask_source.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

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

FrameMaskSource::FrameMaskSource(const io::TumDataset& dataset, const MaskSourceOptions& options,
                                 bool synchronous)
    : source_(options.source) {
  if (source_ == MaskSource::kOracle && !dataset.hasMasks()) {
    util::failAt(dataset.folder() / "mask.txt",
                 "oracle masks requested (--seg oracle) but the dataset has no mask.txt");
  }
  if (source_ == MaskSource::kGeometric || source_ == MaskSource::kFused) {
    geometric_.emplace(dataset.camera());
  }
  if (usesNetwork(source_)) {
    const auto config = segmentation::readModelConfig(options.model_config);
    const auto model =
        segmentation::resolveModelFile(config, options.model_config, options.model_file);
    segmentation::MaskStreamOptions stream;
    stream.synchronous = synchronous;
    semantic_ = std::make_unique<segmentation::SemanticMaskStream>(
        segmentation::SemanticSegmenter(config, model), stream);
  }
}

cv::Mat FrameMaskSource::dynamicMask(const io::RgbdFrame& frame, std::size_t index) {
  switch (source_) {
    case MaskSource::kOracle:
      return frame.mask;
    case MaskSource::kSemantic:
      return semanticMask(frame, index);
    case MaskSource::kGeometric:
      return geometricMask(frame, cv::Mat());
    case MaskSource::kFused: {
      const cv::Mat semantic = semanticMask(frame, index);
      const cv::Mat geometric = geometricMask(frame, semantic);
      if (geometric.empty()) return semantic;
      return semantic | geometric;
    }
    case MaskSource::kNone:
      break;
  }
  return {};
}

cv::Mat FrameMaskSource::semanticMask(const io::RgbdFrame& frame, std::size_t index) {
  return semantic_->masksFor(index, frame.rgb).dynamic;
}

cv::Mat FrameMaskSource::geometricMask(const io::RgbdFrame& frame, const cv::Mat& known_dynamic) {
  segmentation::DepthFrame current{cv::Mat(), frame.depth};
  cv::cvtColor(frame.rgb, current.gray, cv::COLOR_BGR2GRAY);
  cv::Mat dynamic;
  if (!previous_.gray.empty()) dynamic = geometric_->segment(previous_, current, known_dynamic);
  previous_ = std::move(current);
  return dynamic;
}

int FrameMaskSource::networkRuns() const { return semantic_ ? semantic_->networkRuns() : 0; }

double FrameMaskSource::meanNetworkMilliseconds() const {
  return semantic_ ? semantic_->meanNetworkMilliseconds() : 0.0;
}

}  // namespace segslam::system
