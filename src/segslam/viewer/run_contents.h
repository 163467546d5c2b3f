#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace segslam::viewer {

// One entry of map/objects.json: a segmented object with its own point cloud.
struct MapObject {
  std::string id;
  std::string label;
  int instance = 0;
  bool dynamic = false;
  // Path of the object's PLY relative to the run folder (objects.json names it relative to map/).
  std::filesystem::path file;
  // The entry as written, passed on to the page (centroid, bounding box, point count...).
  nlohmann::json attributes;
};

// The occupancy map's files for the page (occupancy/map_files.h), when the run built one.
struct OccupancyContents {
  std::filesystem::path info;                       // map/occupancy.json
  std::filesystem::path occupied_voxels;            // map/occupancy_occupied.ply
  std::optional<std::filesystem::path> floor_grid;  // map/occupancy_2d.pgm
};

struct MapContents {
  std::optional<std::filesystem::path> static_cloud;   // map/static.ply
  std::optional<std::filesystem::path> dynamic_cloud;  // map/dynamic.ply
  std::optional<double> voxel_size;
  std::vector<MapObject> objects;
  std::optional<OccupancyContents> occupancy;
};

// The map points and keyframe centres one session made (map_sessions/ of a run that saved its
// map: system::writeSessionLayers).
struct SessionLayer {
  int session = 0;
  std::filesystem::path points;     // map_sessions/session_<n>_points.ply
  std::filesystem::path keyframes;  // map_sessions/session_<n>_keyframes.ply
};

// What a `segslam run` output folder offers the viewer; every path is relative to the folder.
struct RunContents {
  std::filesystem::path run_dir;
  std::optional<std::filesystem::path> estimate;      // CameraTrajectory.txt
  std::optional<std::filesystem::path> keyframes;     // KeyFrameTrajectory.txt
  std::optional<std::filesystem::path> ground_truth;  // GroundTruthAligned.txt
  std::optional<MapContents> map;                     // absent when the run has no map/ folder
  std::vector<SessionLayer> sessions;                 // by session; empty: no map file saved
};

// Looks at a run folder. Throws util::Error when the folder is missing or map/objects.json is
// malformed or names an object file that does not exist.
RunContents describeRun(const std::filesystem::path& run_dir);

// The description the page loads from /api/run: file entries become URLs under `url_prefix`
// (null when absent).
nlohmann::json runContentsJson(const RunContents& contents, const std::string& url_prefix);

}  // namespace segslam::viewer
