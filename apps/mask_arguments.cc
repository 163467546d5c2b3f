#include "mask_arguments.h"

namespace segslam::apps {

namespace {

std::vector<std::string> allowedSources() {
  std::vector<std::string> names = {"auto"};
  const auto sources = system::maskSourceNames();
  names.insert(names.end(), sources.begin(), sources.end());
  return names;
}

}  // namespace

void addMaskOptions(CLI::App& command, MaskArguments& arguments) {
  command
      .add_option("--seg", arguments.source,
                  "Dynamic masks: auto (fused when the segmentation network is found, else "
                  "geometric), none, oracle (the dataset's ground-truth mask.txt), semantic (a "
                  "segmentation network, see --model-config), geometric (whatever the camera "
                  "motion does not explain) or fused (semantic, then geometric)")
      ->capture_default_str()
      ->check(CLI::IsMember(allowedSources()));
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
  command
      .add_option("--camera-motion", arguments.camera_motion,
                  "Camera motion model of geometric segmentation: rigid (PnP on depth) or "
                  "homography")
      ->capture_default_str()
      ->check(CLI::IsMember({"rigid", "homography"}));
  command
      .add_option("--network-interval", arguments.network_interval,
                  "With --deterministic: run the network on every N-th frame (masks are carried "
                  "to the frames between); 1 scores the network alone")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command
      .add_option("--network-latency", arguments.network_latency,
                  "With --deterministic: use each network output this many frames after its "
                  "frame, as the network's own thread would deliver it (reproducible real-time "
                  "behaviour)")
      ->capture_default_str()
      ->check(CLI::Range(0, 60));
}

system::MaskSourceOptions maskSourceOptions(MaskArguments& arguments) {
  system::MaskSourceOptions options;
  options.model_config = arguments.model_config;
  if (!arguments.model_file.empty()) options.model_file = arguments.model_file;
  if (arguments.source == "auto") {
    arguments.source = system::maskSourceName(system::automaticMaskSource(options).source);
  }
  options.source = system::maskSourceFromName(arguments.source);
  options.network_interval = arguments.network_interval;
  options.network_latency = arguments.network_latency;
  options.geometric.motion_model = segmentation::cameraMotionModelFromName(arguments.camera_motion);
  return options;
}

}  // namespace segslam::apps
