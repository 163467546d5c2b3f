#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/geometry/pose.h"

namespace segslam::map {

// The map file (docs/map_file.md): what tracking needs to continue in a map made by an earlier
// run. A header (magic, format version, section sizes, FNV-1a 64 checksum of the payload) and
// three little-endian sections: the sensor and identity, the keyframes, the map points.
inline constexpr std::uint32_t kMapFileVersion = 1;
inline constexpr std::uint64_t kNoKeyFrame = UINT64_MAX;

// The camera and feature settings the map was made with: a run on another sensor cannot use it.
struct MapFileSensor {
  core::Camera camera;
  double virtual_baseline_m = 0.0;
  double close_depth_baselines = 0.0;
  int pyramid_levels = 0;
  double scale_factor = 0.0;
};

// What else the map depends on: the vocabulary its keyframes' bags of words come from (they are
// recomputed from the descriptors on load, so only its identity is kept), the place recognition
// the run used, and where the dense static map of the run that wrote the file lies.
struct MapFileIdentity {
  std::string vocabulary_file;        // as the run named it; empty: none
  std::uint64_t vocabulary_hash = 0;  // FNV-1a 64 of the vocabulary file; 0: none
  std::string place_recognition;      // the loop detector (bow, vote, cnn)
  std::string dense_map;              // folder of the dense static map; empty: none
};

struct SavedKeyFrame {
  std::uint64_t id = 0;
  std::uint64_t frame_id = 0;
  double timestamp = 0.0;
  std::uint32_t session = 0;  // the run (0 = the first) that made the keyframe
  geometry::Pose T_cw = geometry::Pose::Identity();
  std::uint64_t parent = kNoKeyFrame;  // spanning tree
  std::vector<cv::KeyPoint> keypoints;
  std::vector<cv::KeyPoint> keypoints_un;
  std::vector<float> depth;
  std::vector<float> right_u;
  cv::Mat descriptors;                                     // N x 32, CV_8U
  std::vector<std::pair<std::uint64_t, int>> connections;  // covisible keyframe, weight
  // The loop detector's own description of the keyframe (the CNN's pooled features), opaque
  // here; empty: none (bags of words are recomputed from the descriptors).
  std::string place_description;
};

struct SavedMapPoint {
  std::uint64_t id = 0;
  std::uint64_t first_keyframe_id = 0;
  std::uint32_t session = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  std::array<std::uint8_t, 32> descriptor{};
  double min_distance = 0.0;
  double max_distance = 0.0;
  std::uint64_t reference_keyframe = kNoKeyFrame;
  std::int32_t seen_through = 0;
  std::int32_t moving_votes = 0;
  bool provisional = false;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> observations;  // keyframe, keypoint
};

struct MapFileContents {
  MapFileSensor sensor;
  MapFileIdentity identity;
  std::vector<SavedKeyFrame> keyframes;  // by id
  std::vector<SavedMapPoint> points;     // by id
};

// The whole file. Equal contents give equal bytes.
std::string encodeMapFile(const MapFileContents& contents);
// Throws util::Error, one line naming `file`, for a file that is not a map file, of another
// version, truncated, failing its checksum or inconsistent (an observation of a keyframe the file
// does not hold).
MapFileContents decodeMapFile(std::string_view bytes, const std::filesystem::path& file);

void writeMapFile(const std::filesystem::path& file, const MapFileContents& contents);
MapFileContents readMapFile(const std::filesystem::path& file);

}  // namespace segslam::map
