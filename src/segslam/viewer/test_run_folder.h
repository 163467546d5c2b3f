#pragma once

// A small run folder for the viewer tests only (header-only, never in the library): two
// trajectories and a map with a static cloud, a dynamic cloud and two chairs and a person.

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace segslam::viewer::fixtures {

struct ColouredPoint {
  std::array<float, 3> position;
  std::array<std::uint8_t, 3> colour;
};

// Binary little-endian PLY with float x, y, z and uchar red, green, blue (the map's layout).
inline void writePly(const std::filesystem::path& file, const std::vector<ColouredPoint>& points) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (const auto& point : points) {
    out.write(reinterpret_cast<const char*>(point.position.data()), 3 * sizeof(float));
    out.write(reinterpret_cast<const char*>(point.colour.data()), 3);
  }
}

inline std::vector<ColouredPoint> grid(float x0, float z0, int side, std::uint8_t red) {
  std::vector<ColouredPoint> points;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      points.push_back(
          {{x0 + 0.05f * static_cast<float>(i), 0.5f, z0 + 0.05f * static_cast<float>(j)},
           {red, 120, 80}});
    }
  }
  return points;
}

inline void writeTrajectory(const std::filesystem::path& file, int poses, float z_step) {
  std::ofstream out(file);
  out << "# timestamp tx ty tz qx qy qz qw\n";
  for (int k = 0; k < poses; ++k) {
    out << 100.0 + 0.1 * k << ' ' << 0.02 * k << " 0 " << z_step * static_cast<float>(k)
        << " 0 0 0 1\n";
  }
}

inline void writeObjectsIndex(const std::filesystem::path& file) {
  std::ofstream out(file);
  out << R"({"voxel_size": 0.05, "objects": [
  {"id": "chair_1", "label": "chair", "instance": 1, "dynamic": false, "points": 16,
   "centroid": [0.1, 0.5, 1.1], "bbox_min": [0, 0.5, 1], "bbox_max": [0.15, 0.5, 1.15],
   "file": "objects/chair_1.ply"},
  {"id": "chair_2", "label": "chair", "instance": 2, "dynamic": false, "points": 9,
   "centroid": [1.05, 0.5, 1.05], "bbox_min": [1, 0.5, 1], "bbox_max": [1.1, 0.5, 1.1],
   "file": "objects/chair_2.ply"},
  {"id": "person_1", "label": "person", "instance": 1, "dynamic": true, "points": 4,
   "centroid": [0.5, 0.5, 2.0], "bbox_min": [0.5, 0.5, 2], "bbox_max": [0.55, 0.5, 2.05],
   "file": "objects/person_1.ply"}]})";
}

// Trajectories only (a run made before maps existed) or, with `with_map`, the full layout.
inline void writeRunFolder(const std::filesystem::path& run, bool with_map) {
  std::filesystem::create_directories(run);
  writeTrajectory(run / "CameraTrajectory.txt", 20, 0.03f);
  writeTrajectory(run / "KeyFrameTrajectory.txt", 5, 0.12f);
  if (!with_map) return;
  writePly(run / "map" / "static.ply", grid(-1.0f, 0.0f, 10, 200));
  writePly(run / "map" / "dynamic.ply", grid(0.5f, 2.0f, 3, 250));
  writePly(run / "map" / "objects" / "chair_1.ply", grid(0.0f, 1.0f, 4, 60));
  writePly(run / "map" / "objects" / "chair_2.ply", grid(1.0f, 1.0f, 3, 90));
  writePly(run / "map" / "objects" / "person_1.ply", grid(0.5f, 2.0f, 2, 250));
  writeObjectsIndex(run / "map" / "objects.json");
}

}  // namespace segslam::viewer::fixtures
