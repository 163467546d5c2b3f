#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "segslam/core/trajectory.h"

namespace segslam::io {

// What the poses of a dataset's groundtruth.txt are poses of. The TUM RGB-D benchmark publishes
// the colour camera's poses; the Bonn RGB-D Dynamic dataset publishes the motion-capture
// markers' poses, and documents the camera's as T_ros * T_gt * T_ros * T_m (its README). An ATE
// against the markers' poses measures the marker-to-camera offset as much as the tracking.
enum class GroundTruthFrame { kCamera, kBonnMarkers };

// "camera", "bonn-markers": the names the command line and Python take.
std::vector<std::string> groundTruthFrameNames();
std::optional<GroundTruthFrame> parseGroundTruthFrame(std::string_view name);
// The same, throwing util::Error listing the known names for an unknown one.
GroundTruthFrame requireGroundTruthFrame(std::string_view name);
std::string groundTruthFrameName(GroundTruthFrame frame);
// One line for logs and summaries, e.g. "Bonn motion-capture markers, converted to the camera
// (T_ros * T_gt * T_ros * T_m)".
std::string describeGroundTruthFrame(GroundTruthFrame frame);

// The frame a dataset folder's groundtruth.txt is in, told by the folder's name as the Bonn
// dataset names its sequences ("rgbd_bonn_crowd", ...; a "bonn" token in the name); any other
// folder publishes camera poses.
GroundTruthFrame groundTruthFrameForDataset(const std::filesystem::path& dataset_folder);

// The camera's poses for ground-truth poses given in `frame` (the same poses for kCamera).
core::Trajectory toCameraPoses(const core::Trajectory& ground_truth, GroundTruthFrame frame);

}  // namespace segslam::io
