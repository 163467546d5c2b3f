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
  std::string ground_truth_frame = "auto";
};

// Adds --dataset, --out, --camera, --camera-preset, --max-time-diff and --gt-frame to `command`.
void addDatasetOptions(CLI::App& command, DatasetArguments& arguments);

io::TumDataset openDataset(const DatasetArguments& arguments);

// --gt-frame auto|camera|bonn-markers: what a ground-truth file holds poses of ("auto", for which
// io::parseGroundTruthFrame gives nothing: as the dataset folder's name tells,
// io::groundTruthFrameForDataset).
void addGroundTruthFrameOption(CLI::App& command, std::string& ground_truth_frame);

// For commands that work on a finished run folder with its dataset: --run (required), --dataset,
// --camera, --camera-preset, --max-time-diff and --gt-frame. Without --camera or --camera-preset,
// the camera is the run's camera.yaml, so that it is the one the run used.
void addRunFolderOptions(CLI::App& command, DatasetArguments& arguments,
                         std::filesystem::path& run_dir);
io::TumDataset openRunDataset(DatasetArguments arguments, const std::filesystem::path& run_dir);

// out/<prefix>_<dataset folder name>, used when --out is not given.
std::filesystem::path defaultOutDir(const std::filesystem::path& dataset,
                                    const std::string& prefix);

}  // namespace segslam::apps
