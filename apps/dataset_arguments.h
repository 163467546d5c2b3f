#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "segslam/io/tum_dataset.h"

namespace segslam::apps {

// The dataset and camera options that every command reading a sequence shares.
struct DatasetArguments {
  std::filesystem::path dataset;
  std::filesystem::path out_dir;
  std::string camera_file;
  std::string camera_preset;
  double max_time_difference = 0.02;
};

// Adds --dataset, --out, --camera, --camera-preset and --max-time-diff to `command`.
void addDatasetOptions(CLI::App& command, DatasetArguments& arguments);

io::TumDataset openDataset(const DatasetArguments& arguments);

// For commands that work on a finished run folder with its dataset: --run (required), --dataset,
// --camera, --camera-preset and --max-time-diff. Without --camera or --camera-preset, the camera
// is the run's camera.yaml, so that it is the one the run used.
void addRunFolderOptions(CLI::App& command, DatasetArguments& arguments,
                         std::filesystem::path& run_dir);
io::TumDataset openRunDataset(DatasetArguments arguments, const std::filesystem::path& run_dir);

// out/<prefix>_<dataset folder name>, used when --out is not given.
std::filesystem::path defaultOutDir(const std::filesystem::path& dataset,
                                    const std::string& prefix);

}  // namespace segslam::apps
