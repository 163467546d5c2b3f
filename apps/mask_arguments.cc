#include "mask_arguments.h"

namespace segslam::apps {

void addMaskOptions(CLI::App& command, MaskArguments& arguments) {
  command
      .add_option("--seg", arguments.source,
                  "Dynamic masks: none, oracle (the dataset's ground-truth mask.txt) or semantic "
                  "(a segmentation network, see --model-config)")
      ->capture_default_str()
      ->check(CLI::IsMember(system::maskSourceNames()));
  arguments.model_config =
      std::filesystem::path(SEGSLAM_CONFIG_DIR) / "models" / "espnetv2_voc_384.yaml";
  command
      .add_option("--model-config", arguments.model_config,
                  "Segmentation network description (YAML) for --seg semantic")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  command.add_option("--model", arguments.model_file,
                     "Network file (ONNX) overriding the config's; else the config's path or "
                     "$SEGSLAM_MODEL_DIR");
}

system::MaskSourceOptions maskSourceOptions(const MaskArguments& arguments) {
  system::MaskSourceOptions options;
  options.source = system::maskSourceFromName(arguments.source);
  options.model_config = arguments.model_config;
  if (!arguments.model_file.empty()) options.model_file = arguments.model_file;
  return options;
}

}  // namespace segslam::apps
