#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "segslam/system/mask_source.h"

namespace segslam::apps {

// Where dynamic masks come from, shared by `run` and `eval masks`.
struct MaskArguments {
  std::string source = "auto";
  std::string model_file;
  std::filesystem::path model_config;
  std::string camera_motion = "rigid";
  int network_interval = 5;
  int network_latency = 0;
};

// Adds --seg, --model-config, --model, --camera-motion and --network-interval to `command`.
void addMaskOptions(CLI::App& command, MaskArguments& arguments);

// The options the arguments give. `--seg auto` (the default) becomes the source
// system::automaticMaskSource picks, and `arguments.source` names it from then on.
system::MaskSourceOptions maskSourceOptions(MaskArguments& arguments);

}  // namespace segslam::apps
