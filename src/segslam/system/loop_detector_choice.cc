#include "segslam/system/loop_detector_choice.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "segslam/place/cnn_backbone_config.h"
#include "segslam/place/vocabulary.h"
#include "segslam/util/error.h"

namespace segslam::system {

namespace {

// The backbone `--loop-detector auto` takes: the one named, else the config's; util::Error when
// the config's is not found.
std::string backboneFound(const std::filesystem::path& backbone_config,
                          const place::CnnBackboneConfig& config,
                          const std::optional<std::filesystem::path>& backbone_model) {
  if (backbone_model) return fmt::format("CNN backbone {} (named)", backbone_model->string());
  const auto model = place::resolveBackboneModelFile(config, backbone_config, std::nullopt);
  return fmt::format("CNN backbone {}", model.lexically_normal().string());
}

}  // namespace

AutomaticLoopDetector automaticLoopDetector(
    const std::filesystem::path& backbone_config,
    const std::optional<std::filesystem::path>& backbone_model) {
  const auto config = place::readCnnBackboneConfig(backbone_config);
  try {
    const std::string reason = backboneFound(backbone_config, config, backbone_model);
    spdlog::info("loop candidates: cnn ({})", reason);
    return {"cnn", reason};
  } catch (const util::Error& e) {
    spdlog::warn("loop candidates: bag of words, the CNN backbone is missing: {}", e.what());
    return {"bow", e.what()};
  }
}

const std::vector<std::string>& loopDetectorNames() {
  static const std::vector<std::string> names = {"auto", "bow", "vote", "cnn"};
  return names;
}

namespace {

std::string resolvedDetector(const LoopDetectionRequest& request) {
  const auto& names = loopDetectorNames();
  if (std::find(names.begin(), names.end(), request.detector) == names.end()) {
    throw util::Error(fmt::format("unknown loop detector '{}' (known: {})", request.detector,
                                  fmt::join(names, ", ")));
  }
  if (!request.loop_closing) return "none";
  if (request.detector != "auto") return request.detector;
  return automaticLoopDetector(request.backbone_config, request.backbone_model).detector;
}

loop::CnnLoopBackbone loadBackbone(const LoopDetectionRequest& request) {
  loop::CnnLoopBackbone backbone;
  backbone.config = place::readCnnBackboneConfig(request.backbone_config);
  backbone.config_file = request.backbone_config;
  backbone.model_file = place::resolveBackboneModelFile(backbone.config, request.backbone_config,
                                                        request.backbone_model);
  return backbone;
}

}  // namespace

LoopDetection configureLoopDetection(const LoopDetectionRequest& request, SlamOptions& slam) {
  LoopDetection detection{resolvedDetector(request), {}};
  if (detection.detector == "cnn") slam.loop_backbone = loadBackbone(request);
  const bool bow_loops = detection.detector == "bow";
  if (request.vocabulary == request.shipped_vocabulary &&
      !std::filesystem::exists(request.vocabulary)) {
    spdlog::warn("no vocabulary at {}: relocalisation against the most recent keyframes only{}",
                 request.vocabulary.string(),
                 bow_loops ? ", loop candidates by descriptor vote" : "");
    return detection;
  }
  const auto vocabulary =
      std::make_shared<const place::Vocabulary>(place::Vocabulary::load(request.vocabulary));
  slam.relocalisation_vocabulary = vocabulary;
  detection.vocabulary_file = request.vocabulary;
  if (bow_loops) slam.loop_vocabulary = vocabulary;
  return detection;
}

}  // namespace segslam::system
