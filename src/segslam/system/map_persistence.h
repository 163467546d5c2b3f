#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "segslam/dense/labelled_cloud.h"
#include "segslam/map/map_file.h"
#include "segslam/system/occupancy_output.h"
#include "segslam/system/slam_system.h"

namespace segslam::system {

// A run's map file options (segslam run --load-map, --save-map, --localize-only).
struct MapFileOptions {
  std::optional<std::filesystem::path> load;
  std::optional<std::filesystem::path> save;
  // Track against the loaded map without changing it (SlamOptions::tracker.localize_only).
  bool localize_only = false;
  // A loaded map the camera is not localised in within this many frames stops the run.
  std::size_t frames_to_localise = 30;
  // The vocabulary the run relocalises with (empty: none), recorded as the map's identity.
  std::filesystem::path vocabulary_file;
  std::string place_recognition;
};

struct LoadedMap {
  map::MapFileContents contents;  // keyframes and points as read (the map holds them now)
  std::uintmax_t file_bytes = 0;
  double load_seconds = 0.0;  // reading, checking and restoring
};

// The identity a map made by this run records: the vocabulary's file and FNV-1a 64 hash, the
// place recognition and the dense map folder (empty: none).
map::MapFileIdentity runIdentity(const MapFileOptions& options,
                                 const std::filesystem::path& dense_map);

// Reads `file`, checks that it was made with this system's sensor and with the vocabulary of
// `identity`, and restores it into `slam` (SlamSystem::restoreMap). Throws util::Error, one line
// naming the file, for a bad file or a map made with another camera or vocabulary.
LoadedMap loadMapInto(SlamSystem& slam, const std::filesystem::path& file,
                      const map::MapFileIdentity& identity);

// The static points of the dense map a loaded map links (identity.dense_map / static.ply), for
// this run's map to carry on (dense::MapBuilder::setEarlierMap); none when it links none. A link
// to a map that is no longer there is named in a warning and the run goes on without it.
std::optional<dense::LabelledCloud> linkedDenseMap(const LoadedMap& loaded,
                                                   const std::filesystem::path& file);

// The occupancy map beside that dense map (identity.dense_map / occupancy.bt), for this run's to
// carry on; none when the loaded map links no dense map or its folder holds no occupancy map
// (named in a warning).
std::optional<std::filesystem::path> linkedOccupancyMap(const LoadedMap& loaded,
                                                        const std::filesystem::path& file);

// Writes the map of `slam` to `file` and returns its size. A map that was loaded keeps its sensor
// and, when the run added no keyframe (localisation only), its whole identity, so that the file
// is written again byte for byte.
std::uintmax_t saveMapOf(const SlamSystem& slam, const std::filesystem::path& file,
                         const map::MapFileIdentity& identity, const LoadedMap* loaded);

}  // namespace segslam::system
