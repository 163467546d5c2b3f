#include "segslam/io/ground_truth_frame.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "segslam/geometry/pose.h"
#include "segslam/io/dataset_name.h"
#include "segslam/util/error.h"

namespace segslam::io {

namespace {

// The Bonn RGB-D Dynamic dataset's README: the camera's pose is T_ros * T_gt * T_ros * T_m for a
// published marker pose T_gt. T_ros swaps the y and z axes and turns x around (ROS to optical
// axes); T_m is the markers-to-camera calibration, whose published rotation block is not
// exactly orthonormal (scale 1.016 along x): its nearest rotation is taken.
geometry::Pose bonnRos() {
  geometry::Pose T = geometry::Pose::Identity();
  T.linear() << -1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0;
  return T;
}

geometry::Pose bonnMarkersToCamera() {
  geometry::Pose T = geometry::Pose::Identity();
  T.linear() << 1.0157, 0.1828, -0.2389, 0.0009, -0.8431, -0.6413, -0.3009, 0.6147, -0.8085;
  T.translation() << 0.0113, -0.0098, 0.0111;
  return geometry::orthonormalised(T);
}

}  // namespace

std::vector<std::string> groundTruthFrameNames() { return {"camera", "bonn-markers"}; }

std::optional<GroundTruthFrame> parseGroundTruthFrame(std::string_view name) {
  if (name == "camera") return GroundTruthFrame::kCamera;
  if (name == "bonn-markers") return GroundTruthFrame::kBonnMarkers;
  return std::nullopt;
}

GroundTruthFrame requireGroundTruthFrame(std::string_view name) {
  const auto frame = parseGroundTruthFrame(name);
  if (!frame) {
    throw util::Error(fmt::format("unknown ground truth frame '{}' (known: {})", name,
                                  fmt::join(groundTruthFrameNames(), ", ")));
  }
  return *frame;
}

std::string groundTruthFrameName(GroundTruthFrame frame) {
  return frame == GroundTruthFrame::kBonnMarkers ? "bonn-markers" : "camera";
}

std::string describeGroundTruthFrame(GroundTruthFrame frame) {
  if (frame == GroundTruthFrame::kBonnMarkers) {
    return "Bonn motion-capture markers, converted to the camera (T_ros * T_gt * T_ros * T_m)";
  }
  return "camera poses";
}

GroundTruthFrame groundTruthFrameForDataset(const std::filesystem::path& dataset_folder) {
  return hasNameToken(datasetFolderName(dataset_folder), "bonn") ? GroundTruthFrame::kBonnMarkers
                                                                 : GroundTruthFrame::kCamera;
}

core::Trajectory toCameraPoses(const core::Trajectory& ground_truth, GroundTruthFrame frame) {
  if (frame == GroundTruthFrame::kCamera) return ground_truth;
  const geometry::Pose ros = bonnRos();
  const geometry::Pose markers_to_camera = bonnMarkersToCamera();
  core::Trajectory camera;
  for (const auto& pose : ground_truth.poses()) {
    camera.append(pose.timestamp,
                  geometry::orthonormalised(ros * pose.T_wc * ros * markers_to_camera));
  }
  return camera;
}

}  // namespace segslam::io
