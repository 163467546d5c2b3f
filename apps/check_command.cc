#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>
#include <limits>

#include "commands.h"
#include "dataset_arguments.h"
#include "segslam/io/camera_config.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/system/dataset_check.h"
#include "segslam/util/error.h"
#include "segslam/util/logging.h"
#include "segslam/util/output_folder.h"
#include "segslam/util/progress.h"

namespace segslam::apps {

namespace {

struct CheckOptions : DatasetArguments {
  std::size_t max_frames = std::numeric_limits<std::size_t>::max();
};

void writeJson(const std::filesystem::path& file, const nlohmann::json& json) {
  std::ofstream out(file);
  out << json.dump(2) << "\n";
  if (!out) util::failAt(file, "cannot write");
}

nlohmann::json optionsJson(const CheckOptions& options, const io::TumDataset& dataset) {
  return {{"dataset", std::filesystem::absolute(options.dataset).string()},
          {"out", std::filesystem::absolute(options.out_dir).string()},
          {"camera_source", dataset.cameraSource()},
          {"max_time_difference", options.max_time_difference},
          {"max_frames", std::min(options.max_frames, dataset.size())},
          {"segslam_version", SEGSLAM_VERSION}};
}

void printSummary(const CheckOptions& options, const io::TumDataset& dataset,
                  const system::DatasetCheck& check, double seconds) {
  fmt::print("\nsegslam check: {}\n", options.dataset.string());
  fmt::print("  camera        {} ({}x{}, fx {:.3f})\n", dataset.cameraSource(),
             dataset.camera().width, dataset.camera().height, dataset.camera().fx);
  fmt::print(
      "  frames        {} checked, {:.2f} s of recording at {:.1f} Hz ({:.0f} frames/s read)\n",
      check.frames, check.duration_s, check.mean_frame_rate, check.frames / seconds);
  constexpr std::size_t kAbsentImagesNamed = 5;
  const auto& absent = check.absent_images;
  for (std::size_t i = 0; i < std::min(absent.size(), kAbsentImagesNamed); ++i) {
    fmt::print("  absent        {}:{}: {} is not in the dataset: its frame is left out\n",
               absent[i].list_file.string(), absent[i].line, absent[i].path.string());
  }
  if (absent.size() > kAbsentImagesNamed) {
    fmt::print("  absent        {} more (dataset_check.json names them all)\n",
               absent.size() - kAbsentImagesNamed);
  }
  if (check.skipped_frames > 0) {
    fmt::print("  damaged       {} frames skipped for damaged images (the log names them)\n",
               check.skipped_frames);
  }
  fmt::print("  depth         {:.1f} % valid, {:.2f}-{:.2f} m, colour/depth gap <= {:.1f} ms\n",
             100.0 * check.valid_depth_share, check.min_depth_m, check.max_depth_m,
             1000.0 * check.max_rgb_depth_gap_s);
  if (dataset.hasMasks()) {
    fmt::print("  masks         dynamic pixels in {} frames, {:.2f} % of pixels on average\n",
               check.frames_with_dynamic_pixels, 100.0 * check.mean_dynamic_share);
  }
  fmt::print("  ground truth  {} poses, {} frames associated", check.ground_truth_poses,
             check.frames_with_ground_truth);
  if (check.ground_truth_poses > 0) {
    fmt::print(" ({})", io::describeGroundTruthFrame(check.ground_truth_frame));
  }
  fmt::print("\n");
  fmt::print("  outputs       {}\n", std::filesystem::absolute(options.out_dir).string());
}

void checkCommand(const CheckOptions& options) {
  const auto dataset = openDataset(options);

  util::createOutputFolder(options.out_dir);
  util::addLogFile(options.out_dir / "check.log");
  spdlog::info("dataset {}: {} frames, camera {}", options.dataset.string(), dataset.size(),
               dataset.cameraSource());
  io::writeCameraYaml(options.out_dir / "camera.yaml", dataset.camera());
  writeJson(options.out_dir / "check_config.json", optionsJson(options, dataset));

  util::ProgressBar progress("checking frames", std::min(options.max_frames, dataset.size()));
  const auto check =
      system::checkDataset(dataset, options.max_frames, [&progress] { progress.advance(); });
  progress.finish();
  writeJson(options.out_dir / "dataset_check.json", system::toJson(check));
  printSummary(options, dataset, check, progress.elapsedSeconds());
}

}  // namespace

void registerCheckCommand(CLI::App& app) {
  auto options = std::make_shared<CheckOptions>();
  auto* check = app.add_subcommand(
      "check",
      "Validate an RGB-D sequence in the TUM layout: load every frame and report statistics");
  addDatasetOptions(*check, *options);
  check->add_option("--max-frames", options->max_frames, "Process at most this many frames")
      ->check(CLI::PositiveNumber);
  check->callback([options] {
    if (options->out_dir.empty()) options->out_dir = defaultOutDir(options->dataset, "check");
    checkCommand(*options);
  });
}

}  // namespace segslam::apps
