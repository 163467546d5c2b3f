#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace segslam::io {

// The lower-case name of a dataset folder, also for "." or a path ending in '/': benchmarks name
// their sequences by camera and dataset ("rgbd_dataset_freiburg1_xyz", "rgbd_bonn_crowd").
std::string datasetFolderName(const std::filesystem::path& dataset_folder);

// Whether `token` occurs in `name` as a word of its own: at the start or after a character that
// is not a letter or digit, and not followed by a character of the kind it ends with ("bonn" in
// "rgbd_bonn_crowd", not in "bonnet"; "fr1" in "fr1xyz", not in "fr12").
bool hasNameToken(std::string_view name, std::string_view token);

}  // namespace segslam::io
