#include "segslam/system/loop_detector_choice.h"

#include <fmt/format.h>

#include "segslam/place/cnn_backbone_config.h"
#include "segslam/util/error.h"

namespace segslam::system {

AutomaticLoopDetector automaticLoopDetector(
    const std::filesystem::path& backbone_config,
    const std::optional<std::filesystem::path>& backbone_model) {
  const auto config = place::readCnnBackboneConfig(backbone_config);
  if (backbone_model) {
    return {"cnn", fmt::format("CNN backbone {} (named)", backbone_model->string())};
  }
  try {
    const auto model = place::resolveBackboneModelFile(config, backbone_config, std::nullopt);
    return {"cnn", fmt::format("CNN backbone {}", model.lexically_normal().string())};
  } catch (const util::Error& e) {
    return {"bow", e.what()};
  }
}

}  // namespace segslam::system
