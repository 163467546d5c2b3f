#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "segslam/map/keyframe.h"
#include "segslam/map/map_point.h"

namespace segslam::map {

// The map: keyframes and map points. `mutex` guards every keyframe and map point: tracking holds
// it while it handles a frame, local mapping while it reads or writes the map (never while it
// optimises). Keyframes and points that go bad stay owned here, so raw pointers between them
// never dangle; clear() breaks the shared_ptr cycles at shutdown.
class Map {
 public:
  Map() = default;
  ~Map();
  Map(const Map&) = delete;
  Map& operator=(const Map&) = delete;

  std::shared_ptr<KeyFrame> createKeyFrame(const Frame& frame);
  std::shared_ptr<MapPoint> createMapPoint(const Eigen::Vector3d& position, KeyFrame* reference);
  // A keyframe / point of a saved map (map::restoreMap) under its saved id; ids made later
  // continue after the largest restored one.
  std::shared_ptr<KeyFrame> restoreKeyFrame(std::uint64_t id, const Frame& frame);
  std::shared_ptr<MapPoint> restoreMapPoint(std::uint64_t id, const Eigen::Vector3d& position,
                                            KeyFrame* reference);

  // Live (not bad) keyframes / map points, ordered by id.
  [[nodiscard]] std::vector<std::shared_ptr<KeyFrame>> keyFrames() const;
  [[nodiscard]] std::vector<std::shared_ptr<MapPoint>> mapPoints() const;
  [[nodiscard]] std::size_t numKeyFrames() const;
  [[nodiscard]] std::size_t numMapPoints() const;
  // Drops bad map points from the store (they may still be referenced by frames in flight).
  void pruneBadMapPoints();
  // Frees the features of culled keyframes up to id `last_done` (KeyFrame::releaseFeatures): the
  // last stage of the keyframe pipeline calls it once it is done with that keyframe, so memory
  // follows the live keyframes, not every keyframe ever made. Returns how many were freed.
  std::size_t releaseCulledKeyFrames(std::uint64_t last_done);
  void clear();

  // Counts rewrites of the whole map (loop correction, global BA), so that tracking knows when
  // to re-anchor its last frame on its reference keyframe.
  void notifyCorrection() { ++corrections_; }
  [[nodiscard]] std::uint64_t corrections() const { return corrections_; }

  mutable std::mutex mutex;

 private:
  std::vector<std::shared_ptr<KeyFrame>> keyframes_;
  std::vector<std::shared_ptr<MapPoint>> map_points_;
  std::uint64_t next_keyframe_id_ = 0;
  std::uint64_t next_map_point_id_ = 0;
  std::uint64_t corrections_ = 0;
};

}  // namespace segslam::map
