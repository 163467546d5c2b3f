#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace segslam::util {

// The network file a model config names, first found of: `override_file` (a --model flag; must
// exist), `model` (absolute, or relative to the config file's folder), and its file name in
// $SEGSLAM_MODEL_DIR. util::Error listing the places tried when none exists; `kind` names the
// network in messages ("segmentation model").
std::filesystem::path findModelFile(const std::filesystem::path& model,
                                    const std::filesystem::path& config_file,
                                    const std::optional<std::filesystem::path>& override_file,
                                    const std::string& kind,
                                    const std::string& override_flag = "--model");

}  // namespace segslam::util
