#include "dataset_arguments.h"

#include "segslam/io/camera_config.h"

namespace segslam::apps {

void addDatasetOptions(CLI::App& command, DatasetArguments& arguments) {
  command.add_option("-d,--dataset", arguments.dataset, "Dataset folder (rgb.txt, depth.txt, ...)")
      ->required()
      ->check(CLI::ExistingDirectory);
  command.add_option("-o,--out", arguments.out_dir,
                     "Output folder (default: out/" + command.get_name() + "_<dataset name>)");
  command.add_option("--camera", arguments.camera_file, "Camera settings YAML (overrides presets)");
  command.add_option("--camera-preset", arguments.camera_preset, "Camera preset")
      ->check(CLI::IsMember(io::cameraPresetNames()));
  command
      .add_option("--max-time-diff", arguments.max_time_difference,
                  "Max colour/depth timestamp difference for association (s)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  addGroundTruthFrameOption(command, arguments.ground_truth_frame);
}

void addGroundTruthFrameOption(CLI::App& command, std::string& ground_truth_frame) {
  std::vector<std::string> names = io::groundTruthFrameNames();
  names.insert(names.begin(), "auto");
  command
      .add_option("--gt-frame", ground_truth_frame,
                  "What the ground truth holds poses of: camera, or bonn-markers (the Bonn RGB-D "
                  "Dynamic dataset's, converted to the camera's); auto: bonn-markers for the "
                  "groundtruth.txt of a folder named like a Bonn sequence (rgbd_bonn_*), else "
                  "camera")
      ->check(CLI::IsMember(names))
      ->capture_default_str();
}

io::TumDataset openDataset(const DatasetArguments& arguments) {
  io::DatasetOptions options;
  options.max_time_difference = arguments.max_time_difference;
  if (!arguments.camera_file.empty()) options.camera_file = arguments.camera_file;
  if (!arguments.camera_preset.empty()) options.camera_preset = arguments.camera_preset;
  options.ground_truth_frame = io::parseGroundTruthFrame(arguments.ground_truth_frame);
  return io::TumDataset::open(arguments.dataset, options);
}

void addRunFolderOptions(CLI::App& command, DatasetArguments& arguments,
                         std::filesystem::path& run_dir) {
  command.add_option("--run", run_dir, "Run folder written by `segslam run`")
      ->required()
      ->check(CLI::ExistingDirectory);
  command.add_option("-d,--dataset", arguments.dataset, "The run's dataset folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  command.add_option("--camera", arguments.camera_file,
                     "Camera settings YAML (default: the run's camera.yaml)");
  command.add_option("--camera-preset", arguments.camera_preset, "Camera preset")
      ->check(CLI::IsMember(io::cameraPresetNames()));
  command
      .add_option("--max-time-diff", arguments.max_time_difference,
                  "Max colour/depth timestamp difference for association (s)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  addGroundTruthFrameOption(command, arguments.ground_truth_frame);
}

io::TumDataset openRunDataset(DatasetArguments arguments, const std::filesystem::path& run_dir) {
  const auto run_camera = run_dir / "camera.yaml";
  if (arguments.camera_file.empty() && arguments.camera_preset.empty() &&
      std::filesystem::exists(run_camera)) {
    arguments.camera_file = run_camera.string();
  }
  return openDataset(arguments);
}

std::filesystem::path defaultOutDir(const std::filesystem::path& dataset,
                                    const std::string& prefix) {
  const auto name = std::filesystem::weakly_canonical(dataset).filename().string();
  return std::filesystem::path("out") / (prefix + "_" + (name.empty() ? "dataset" : name));
}

}  // namespace segslam::apps
