#pragma once

#include <cstdint>
#include <map>
#include <memory>

#include "segslam/map/frame.h"
#include "segslam/map/map.h"
#include "segslam/map/map_file.h"

namespace segslam::map {

// Which run made each keyframe and map point: the runs that saved and loaded a map are its
// sessions (0 = the first). What the current run makes belongs to `current`.
struct MapSessions {
  std::map<std::uint64_t, std::uint32_t> keyframes;
  std::map<std::uint64_t, std::uint32_t> points;
  std::uint32_t current = 0;

  [[nodiscard]] std::uint32_t ofKeyFrame(std::uint64_t id) const;
  [[nodiscard]] std::uint32_t ofPoint(std::uint64_t id) const;
};

// The live keyframes and map points of `map` as the map file holds them (the caller holds
// map.mutex). Observations of culled keyframes and culled points are left out.
MapFileContents captureMap(const Map& map, const MapSessions& sessions);

// Builds the saved keyframes and points into `map`, which must be empty, with their ids,
// covisibility graph and spanning tree; the keyframes share `camera`. Returns the sessions of
// what was restored, `current` being the next session.
MapSessions restoreMap(const MapFileContents& contents,
                       const std::shared_ptr<const FrameCamera>& camera, Map& map);

}  // namespace segslam::map
