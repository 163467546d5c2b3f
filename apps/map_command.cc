#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "dataset_arguments.h"
#include "occupancy_arguments.h"
#include "segslam/system/map_rebuild.h"
#include "segslam/util/output_folder.h"

namespace segslam::apps {

namespace {

struct MapOptions : DatasetArguments {
  std::filesystem::path run_dir;
  std::string masks = "oracle";
  std::filesystem::path model_config =
      std::filesystem::path(SEGSLAM_CONFIG_DIR) / "models" / "espnetv2_voc_384.yaml";
  std::filesystem::path model_file;
  system::MapRebuildOptions rebuild;
};

void mapCommand(MapOptions& options) {
  const auto dataset = openRunDataset(options, options.run_dir);
  util::createOutputFolder(options.run_dir / "map");
  options.rebuild.oracle_masks = options.masks == "oracle";
  if (options.masks == "semantic") {
    options.rebuild.model_config = options.model_config;
    if (!options.model_file.empty()) options.rebuild.model_file = options.model_file;
  }
  const auto s = system::rebuildMap(dataset, options.run_dir, options.rebuild);
  fmt::print(
      "segslam map: {} static and {} dynamic points, {} objects from {} keyframes in "
      "{:.1f} s\n  outputs    {}\n",
      s.static_points, s.dynamic_points, s.objects, s.keyframes, s.build_seconds,
      std::filesystem::absolute(options.run_dir / "map").string());
  if (s.occupancy) printOccupancySummary(*s.occupancy);
}

}  // namespace

void registerMapCommand(CLI::App& app) {
  auto options = std::make_shared<MapOptions>();
  auto* command = app.add_subcommand(
      "map",
      "Rebuild a run's dense map (map/ in the run folder) from its KeyFrameTrajectory.txt and "
      "the dataset's images");
  addRunFolderOptions(*command, *options, options->run_dir);
  command
      ->add_option("--seg", options->masks,
                   "Dynamic masks of the keyframes: oracle (mask.txt), none, or semantic (the "
                   "network segments each keyframe; its labels give the objects)")
      ->check(CLI::IsMember(std::vector<std::string>{"oracle", "none", "semantic"}))
      ->capture_default_str();
  command
      ->add_option("--model-config", options->model_config,
                   "Segmentation network description (YAML) for --seg semantic")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  command->add_option("--model", options->model_file,
                      "Network file (ONNX) overriding the config's; else the config's path or "
                      "$SEGSLAM_MODEL_DIR");
  command
      ->add_option("--mask-dilation", options->rebuild.map.keyframe.mask_dilation_px,
                   "Dilation of the dynamic mask before the static map is taken (pixels)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--map-voxel", options->rebuild.map.keyframe.voxel_size,
                   "Voxel size of the dense map (metres)")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 1.0));
  command
      ->add_option("--map-outlier-neighbours", options->rebuild.map.cleaning.outlier_neighbours,
                   "Neighbours of the map's statistical outlier removal (0: no removal)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  addOccupancyOptions(*command, options->rebuild.occupancy);
  command->callback([options] { mapCommand(*options); });
}

}  // namespace segslam::apps
