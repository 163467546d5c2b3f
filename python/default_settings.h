#pragma once

#include <filesystem>

// The settings files shipped in config/ that the Python module uses when none are named: the
// same defaults as the CLI's.
namespace segslam::python {

inline std::filesystem::path configDir() { return SEGSLAM_CONFIG_DIR; }
inline std::filesystem::path defaultSegmentationConfig() {
  return configDir() / "models" / "espnetv2_voc_384.yaml";
}
inline std::filesystem::path defaultBackboneConfig() {
  return configDir() / "models" / "tiny_darknet_imagenet.yaml";
}

}  // namespace segslam::python
