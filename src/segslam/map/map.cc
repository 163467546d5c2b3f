#include "segslam/map/map.h"

#include <algorithm>

namespace segslam::map {

Map::~Map() { clear(); }

std::shared_ptr<KeyFrame> Map::createKeyFrame(const Frame& frame) {
  auto keyframe = std::make_shared<KeyFrame>(next_keyframe_id_++, frame);
  keyframes_.push_back(keyframe);
  return keyframe;
}

std::shared_ptr<MapPoint> Map::createMapPoint(const Eigen::Vector3d& position,
                                              KeyFrame* reference) {
  auto point = std::make_shared<MapPoint>(next_map_point_id_++, position, reference);
  map_points_.push_back(point);
  return point;
}

std::shared_ptr<KeyFrame> Map::restoreKeyFrame(std::uint64_t id, const Frame& frame) {
  auto keyframe = std::make_shared<KeyFrame>(id, frame);
  keyframes_.push_back(keyframe);
  next_keyframe_id_ = std::max(next_keyframe_id_, id + 1);
  return keyframe;
}

std::shared_ptr<MapPoint> Map::restoreMapPoint(std::uint64_t id, const Eigen::Vector3d& position,
                                               KeyFrame* reference) {
  auto point = std::make_shared<MapPoint>(id, position, reference);
  map_points_.push_back(point);
  next_map_point_id_ = std::max(next_map_point_id_, id + 1);
  return point;
}

std::vector<std::shared_ptr<KeyFrame>> Map::keyFrames() const {
  std::vector<std::shared_ptr<KeyFrame>> live;
  for (const auto& k : keyframes_) {
    if (!k->bad) live.push_back(k);
  }
  return live;
}

std::vector<std::shared_ptr<MapPoint>> Map::mapPoints() const {
  std::vector<std::shared_ptr<MapPoint>> live;
  for (const auto& p : map_points_) {
    if (!p->bad) live.push_back(p);
  }
  return live;
}

std::size_t Map::numKeyFrames() const {
  return std::count_if(keyframes_.begin(), keyframes_.end(), [](const auto& k) { return !k->bad; });
}

std::size_t Map::numMapPoints() const {
  return std::count_if(map_points_.begin(), map_points_.end(),
                       [](const auto& p) { return !p->bad; });
}

void Map::pruneBadMapPoints() {
  std::erase_if(map_points_, [](const auto& p) { return p->bad; });
}

std::size_t Map::releaseCulledKeyFrames(std::uint64_t last_done) {
  std::size_t released = 0;
  for (const auto& k : keyframes_) {
    if (k->id > last_done) break;  // keyframes_ is ordered by id
    if (k->bad && !k->released()) {
      k->releaseFeatures();
      ++released;
    }
  }
  return released;
}

void Map::clear() {
  // Keyframes hold their points and points are reached through keyframes: dropping the
  // keyframes' point lists and the points' back-references frees both.
  for (const auto& p : map_points_) p->replaced_by.reset();
  for (const auto& k : keyframes_) {
    for (std::size_t i = 0; i < k->size(); ++i) k->eraseMapPoint(i);
  }
  keyframes_.clear();
  map_points_.clear();
}

}  // namespace segslam::map
