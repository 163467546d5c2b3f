#include "segslam/system/mask_source.h"

#include <fmt/format.h>

#include "segslam/util/error.h"

namespace segslam::system {

std::vector<std::string> maskSourceNames() { return {"none", "oracle", "semantic"}; }

MaskSource maskSourceFromName(const std::string& name) {
  if (name == "oracle") return MaskSource::kOracle;
  if (name == "semantic") return MaskSource::kSemantic;
  if (name == "none") return MaskSource::kNone;
  throw util::Error(
      fmt::format("unknown mask source '{}' (known: none, oracle, semantic)", name));
}

std::string maskSourceName(MaskSource source) {
  switch (source) {
    case MaskSource::kOracle:
      return "oracle";
    case MaskSource::kSemantic:
      return "semantic";
    case MaskSource::kNone:
      break;
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
  if (source_ == MaskSource::kSemantic) {
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
      return semantic_->masksFor(index, frame.rgb).dynamic;
    case MaskSource::kNone:
      break;
  }
  return {};
}

int FrameMaskSource::networkRuns() const { return semantic_ ? semantic_->networkRuns() : 0; }

double FrameMaskSource::meanNetworkMilliseconds() const {
  return semantic_ ? semantic_->meanNetworkMilliseconds() : 0.0;
}

}  // namespace segslam::system
