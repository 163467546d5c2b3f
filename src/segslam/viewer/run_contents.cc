#include "segslam/viewer/run_contents.h"

#include <fmt/format.h>

#include <fstream>

#include "segslam/occupancy/map_files.h"
#include "segslam/util/error.h"

namespace segslam::viewer {

namespace {

namespace fs = std::filesystem;

std::optional<fs::path> existingFile(const fs::path& run_dir, const fs::path& relative) {
  if (fs::is_regular_file(run_dir / relative)) return relative;
  return std::nullopt;
}

const nlohmann::json& requireMember(const fs::path& file, const nlohmann::json& object,
                                    const char* key, nlohmann::json::value_t type,
                                    const char* type_name) {
  const auto it = object.find(key);
  if (it == object.end() || it->type() != type) {
    util::failAt(file, fmt::format("every object needs \"{}\" ({})", key, type_name));
  }
  return *it;
}

// objects.json names files relative to map/; they must stay inside it.
fs::path objectFile(const fs::path& index_file, const fs::path& run_dir, const std::string& file) {
  const fs::path inside_map = fs::path(file).lexically_normal();
  if (fs::path(file).is_absolute() || inside_map.empty() || *inside_map.begin() == "..") {
    util::failAt(index_file, fmt::format("object file \"{}\" is outside the map folder", file));
  }
  const fs::path relative = fs::path("map") / inside_map;
  if (!fs::is_regular_file(run_dir / relative)) {
    util::failAt(index_file, fmt::format("object file {} does not exist", relative.string()));
  }
  return relative;
}

MapObject parseObject(const fs::path& index_file, const fs::path& run_dir,
                      const nlohmann::json& entry) {
  using Type = nlohmann::json::value_t;
  if (!entry.is_object()) util::failAt(index_file, "every entry of \"objects\" must be an object");
  MapObject object;
  object.id = requireMember(index_file, entry, "id", Type::string, "a string");
  object.label = requireMember(index_file, entry, "label", Type::string, "a string");
  const auto& file = requireMember(index_file, entry, "file", Type::string, "a string");
  object.file = objectFile(index_file, run_dir, file.get<std::string>());
  if (const auto it = entry.find("instance"); it != entry.end() && it->is_number_integer()) {
    object.instance = it->get<int>();
  }
  if (const auto it = entry.find("dynamic"); it != entry.end() && it->is_boolean()) {
    object.dynamic = it->get<bool>();
  }
  object.attributes = entry;
  return object;
}

void readObjectsIndex(const fs::path& run_dir, MapContents& map) {
  const fs::path index_file = run_dir / "map" / "objects.json";
  if (!fs::exists(index_file)) return;
  std::ifstream in(index_file);
  const auto index = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (index.is_discarded() || !index.is_object()) {
    util::failAt(index_file, "not a JSON object");
  }
  if (const auto it = index.find("voxel_size"); it != index.end() && it->is_number()) {
    map.voxel_size = it->get<double>();
  }
  const auto objects = index.find("objects");
  if (objects == index.end() || !objects->is_array()) {
    util::failAt(index_file, "\"objects\" must be an array");
  }
  for (const auto& entry : *objects) map.objects.push_back(parseObject(index_file, run_dir, entry));
}

nlohmann::json urlOrNull(const std::optional<fs::path>& file, const std::string& url_prefix) {
  if (!file) return nullptr;
  return url_prefix + file->generic_string();
}

nlohmann::json mapJson(const MapContents& map, const std::string& url_prefix) {
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& object : map.objects) {
    nlohmann::json entry = object.attributes;
    entry["id"] = object.id;
    entry["label"] = object.label;
    entry["instance"] = object.instance;
    entry["dynamic"] = object.dynamic;
    entry["url"] = url_prefix + object.file.generic_string();
    objects.push_back(std::move(entry));
  }
  nlohmann::json occupancy;
  if (const auto& o = map.occupancy) {
    occupancy = {{"info", url_prefix + o->info.generic_string()},
                 {"voxels", url_prefix + o->occupied_voxels.generic_string()},
                 {"grid", urlOrNull(o->floor_grid, url_prefix)}};
  }
  return {{"static", urlOrNull(map.static_cloud, url_prefix)},
          {"dynamic", urlOrNull(map.dynamic_cloud, url_prefix)},
          {"voxel_size", map.voxel_size ? nlohmann::json(*map.voxel_size) : nlohmann::json()},
          {"objects", std::move(objects)},
          {"occupancy", std::move(occupancy)}};
}

// The occupancy files, when the map folder has both the description and the voxels.
std::optional<OccupancyContents> occupancyContents(const fs::path& run_dir) {
  const auto info = existingFile(run_dir, fs::path("map") / occupancy::kOccupancyInfoFile);
  const auto voxels = existingFile(run_dir, fs::path("map") / occupancy::kOccupiedVoxelsFile);
  if (!info || !voxels) return std::nullopt;
  return OccupancyContents{*info, *voxels,
                           existingFile(run_dir, fs::path("map") / occupancy::kFloorGridImage)};
}

// map_sessions/session_<n>_points.ply with its keyframes beside it, by session.
std::vector<SessionLayer> sessionLayers(const fs::path& run_dir) {
  std::vector<SessionLayer> layers;
  if (!fs::is_directory(run_dir / "map_sessions")) return layers;
  for (int session = 0;; ++session) {
    const fs::path points =
        fs::path("map_sessions") / fmt::format("session_{}_points.ply", session);
    const fs::path keyframes =
        fs::path("map_sessions") / fmt::format("session_{}_keyframes.ply", session);
    if (!fs::is_regular_file(run_dir / points) || !fs::is_regular_file(run_dir / keyframes)) break;
    layers.push_back({session, points, keyframes});
  }
  return layers;
}

nlohmann::json sessionsJson(const std::vector<SessionLayer>& sessions,
                            const std::string& url_prefix) {
  nlohmann::json json = nlohmann::json::array();
  for (const auto& layer : sessions) {
    json.push_back({{"session", layer.session},
                    {"points", url_prefix + layer.points.generic_string()},
                    {"keyframes", url_prefix + layer.keyframes.generic_string()}});
  }
  return json;
}

}  // namespace

RunContents describeRun(const fs::path& run_dir) {
  if (!fs::is_directory(run_dir)) util::failAt(run_dir, "run folder does not exist");
  RunContents contents;
  contents.run_dir = run_dir;
  contents.estimate = existingFile(run_dir, "CameraTrajectory.txt");
  contents.keyframes = existingFile(run_dir, "KeyFrameTrajectory.txt");
  contents.ground_truth = existingFile(run_dir, "GroundTruthAligned.txt");
  if (fs::is_directory(run_dir / "map")) {
    MapContents map;
    map.static_cloud = existingFile(run_dir, fs::path("map") / "static.ply");
    map.dynamic_cloud = existingFile(run_dir, fs::path("map") / "dynamic.ply");
    readObjectsIndex(run_dir, map);
    map.occupancy = occupancyContents(run_dir);
    contents.map = std::move(map);
  }
  contents.sessions = sessionLayers(run_dir);
  return contents;
}

nlohmann::json runContentsJson(const RunContents& contents, const std::string& url_prefix) {
  const auto name = fs::absolute(contents.run_dir).lexically_normal();
  return {
      {"name", (name.has_filename() ? name : name.parent_path()).filename().string()},
      {"trajectories",
       {{"estimate", urlOrNull(contents.estimate, url_prefix)},
        {"keyframes", urlOrNull(contents.keyframes, url_prefix)},
        {"ground_truth", urlOrNull(contents.ground_truth, url_prefix)}}},
      {"map", contents.map ? mapJson(*contents.map, url_prefix) : nlohmann::json()},
      {"sessions", sessionsJson(contents.sessions, url_prefix)},
  };
}

}  // namespace segslam::viewer
