#include "segslam/system/map_persistence.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

#include "segslam/dense/ply_io.h"
#include "segslam/util/byte_stream.h"
#include "segslam/util/elapsed_time.h"
#include "segslam/util/error.h"
#include "segslam/util/text_file.h"

namespace segslam::system {

namespace {

std::string describeSensor(const map::MapFileSensor& s) {
  const core::Camera& c = s.camera;
  return fmt::format(
      "{}x{} fx {:.3f} fy {:.3f} cx {:.3f} cy {:.3f} distortion [{}] depth factor {:g}, baseline "
      "{:.4f} m, {} pyramid levels x {:g}",
      c.width, c.height, c.fx, c.fy, c.cx, c.cy, fmt::join(c.distortion, " "), c.depth_factor,
      s.virtual_baseline_m, s.pyramid_levels, s.scale_factor);
}

// The camera's name and frame rate do not change what the map means; everything else does.
bool sameSensor(const map::MapFileSensor& a, const map::MapFileSensor& b) {
  const core::Camera& x = a.camera;
  const core::Camera& y = b.camera;
  return x.width == y.width && x.height == y.height && x.fx == y.fx && x.fy == y.fy &&
         x.cx == y.cx && x.cy == y.cy && x.distortion == y.distortion &&
         x.depth_factor == y.depth_factor && a.virtual_baseline_m == b.virtual_baseline_m &&
         a.close_depth_baselines == b.close_depth_baselines &&
         a.pyramid_levels == b.pyramid_levels && a.scale_factor == b.scale_factor;
}

void checkIdentity(const std::filesystem::path& file, const map::MapFileContents& contents,
                   const map::MapFileSensor& sensor, const map::MapFileIdentity& identity) {
  if (!sameSensor(contents.sensor, sensor)) {
    util::failAt(file, fmt::format("map made with another camera ({}); this run's is {}",
                                   describeSensor(contents.sensor), describeSensor(sensor)));
  }
  const map::MapFileIdentity& made_with = contents.identity;
  if (made_with.vocabulary_hash != 0 && made_with.vocabulary_hash != identity.vocabulary_hash) {
    util::failAt(
        file, fmt::format("map made with another vocabulary ({}, hash {:016x}); this run uses {}",
                          made_with.vocabulary_file, made_with.vocabulary_hash,
                          identity.vocabulary_hash == 0
                              ? std::string("none")
                              : fmt::format("{}, hash {:016x}", identity.vocabulary_file,
                                            identity.vocabulary_hash)));
  }
}

}  // namespace

map::MapFileIdentity runIdentity(const MapFileOptions& options,
                                 const std::filesystem::path& dense_map) {
  map::MapFileIdentity identity;
  if (!options.vocabulary_file.empty()) {
    identity.vocabulary_file = options.vocabulary_file.string();
    identity.vocabulary_hash = util::fnv1a64(util::readTextFile(options.vocabulary_file));
  }
  identity.place_recognition = options.place_recognition;
  if (!dense_map.empty()) identity.dense_map = std::filesystem::absolute(dense_map).string();
  return identity;
}

LoadedMap loadMapInto(SlamSystem& slam, const std::filesystem::path& file,
                      const map::MapFileIdentity& identity) {
  const auto start = std::chrono::steady_clock::now();
  LoadedMap loaded;
  loaded.contents = map::readMapFile(file);
  checkIdentity(file, loaded.contents, slam.mapSensor(), identity);
  if (loaded.contents.keyframes.empty()) util::failAt(file, "map file holds no keyframe");
  slam.restoreMap(loaded.contents);
  loaded.file_bytes = std::filesystem::file_size(file);
  loaded.load_seconds = util::millisecondsSince(start) / 1000.0;
  return loaded;
}

std::optional<dense::LabelledCloud> linkedDenseMap(const LoadedMap& loaded,
                                                   const std::filesystem::path& file) {
  const std::string& folder = loaded.contents.identity.dense_map;
  if (folder.empty()) return std::nullopt;
  const std::filesystem::path points = std::filesystem::path(folder) / "static.ply";
  if (!std::filesystem::exists(points)) {
    spdlog::warn("{}: its dense map {} is gone; this run's map holds only what it sees",
                 file.string(), points.string());
    return std::nullopt;
  }
  return dense::readPly(points);
}

std::optional<std::filesystem::path> linkedOccupancyMap(const LoadedMap& loaded,
                                                        const std::filesystem::path& file) {
  const std::string& folder = loaded.contents.identity.dense_map;
  if (folder.empty()) return std::nullopt;
  const std::filesystem::path occupancy = std::filesystem::path(folder) / occupancy::kOccupancyFile;
  if (!std::filesystem::exists(occupancy)) {
    spdlog::warn("{}: its map folder {} holds no occupancy map; this run's holds only what it sees",
                 file.string(), folder);
    return std::nullopt;
  }
  return occupancy;
}

std::uintmax_t saveMapOf(const SlamSystem& slam, const std::filesystem::path& file,
                         const map::MapFileIdentity& identity, const LoadedMap* loaded) {
  map::MapFileContents contents = slam.captureMap();
  contents.sensor = slam.mapSensor();
  contents.identity = identity;
  if (loaded) {
    contents.sensor = loaded->contents.sensor;
    const std::uint32_t session = slam.sessions().current;
    const bool extended = std::any_of(contents.keyframes.begin(), contents.keyframes.end(),
                                      [&](const auto& k) { return k.session == session; });
    if (!extended) contents.identity = loaded->contents.identity;
  }
  map::writeMapFile(file, contents);
  return std::filesystem::file_size(file);
}

}  // namespace segslam::system
