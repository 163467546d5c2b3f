#include "segslam/map/map_snapshot.h"

#include <algorithm>
#include <cstring>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace segslam::map {

namespace {

SavedKeyFrame saveKeyFrame(const KeyFrame& keyframe, std::uint32_t session,
                           const std::set<std::uint64_t>& live) {
  SavedKeyFrame saved;
  saved.id = keyframe.id;
  saved.frame_id = keyframe.frame_id;
  saved.timestamp = keyframe.timestamp;
  saved.session = session;
  saved.T_cw = keyframe.T_cw;
  if (keyframe.parent != nullptr && live.count(keyframe.parent->id) > 0) {
    saved.parent = keyframe.parent->id;
  }
  saved.keypoints = keyframe.keypoints;
  saved.keypoints_un = keyframe.keypoints_un;
  saved.depth = keyframe.depth;
  saved.right_u = keyframe.right_u;
  saved.descriptors = keyframe.descriptors;
  // Ordered by id, so that equal graphs give equal files.
  for (KeyFrame* other : keyframe.covisiblesWithWeight(0)) {
    if (live.count(other->id) > 0) {
      saved.connections.emplace_back(other->id, keyframe.weight(other));
    }
  }
  std::sort(saved.connections.begin(), saved.connections.end());
  return saved;
}

SavedMapPoint savePoint(const MapPoint& point, std::uint32_t session,
                        const std::set<std::uint64_t>& live) {
  SavedMapPoint saved;
  saved.id = point.id;
  saved.first_keyframe_id = point.first_keyframe_id;
  saved.session = session;
  saved.position = point.position;
  saved.normal = point.normal;
  if (!point.descriptor.empty()) {
    std::memcpy(saved.descriptor.data(), point.descriptor.data, saved.descriptor.size());
  }
  saved.min_distance = point.min_distance;
  saved.max_distance = point.max_distance;
  saved.seen_through = point.seen_through;
  saved.moving_votes = point.moving_votes;
  saved.provisional = point.provisional;
  for (const auto& [keyframe, index] : point.observations()) {
    if (live.count(keyframe->id) > 0) {
      saved.observations.emplace_back(keyframe->id, static_cast<std::uint32_t>(index));
    }
  }
  // A reference that is gone is replaced as restoreMap() would replace it, so that a saved map
  // loaded and saved again gives the same file.
  if (point.reference_keyframe != nullptr && live.count(point.reference_keyframe->id) > 0) {
    saved.reference_keyframe = point.reference_keyframe->id;
  } else if (!saved.observations.empty()) {
    saved.reference_keyframe = saved.observations.front().first;
  }
  return saved;
}

Frame keyFrameContents(const SavedKeyFrame& saved,
                       const std::shared_ptr<const FrameCamera>& camera) {
  Frame frame;
  frame.id = saved.frame_id;
  frame.timestamp = saved.timestamp;
  frame.camera = camera;
  frame.keypoints = saved.keypoints;
  frame.keypoints_un = saved.keypoints_un;
  frame.depth = saved.depth;
  frame.right_u = saved.right_u;
  frame.descriptors = saved.descriptors;
  frame.grid = KeypointGrid(frame.keypoints_un, camera->undistorted_bounds);
  frame.T_cw = saved.T_cw;
  frame.has_pose = true;
  return frame;
}

}  // namespace

std::uint32_t MapSessions::ofKeyFrame(std::uint64_t id) const {
  const auto it = keyframes.find(id);
  return it == keyframes.end() ? current : it->second;
}

std::uint32_t MapSessions::ofPoint(std::uint64_t id) const {
  const auto it = points.find(id);
  return it == points.end() ? current : it->second;
}

MapFileContents captureMap(const Map& map, const MapSessions& sessions) {
  MapFileContents contents;
  const auto keyframes = map.keyFrames();
  std::set<std::uint64_t> live;
  for (const auto& keyframe : keyframes) live.insert(keyframe->id);
  for (const auto& keyframe : keyframes) {
    contents.keyframes.push_back(saveKeyFrame(*keyframe, sessions.ofKeyFrame(keyframe->id), live));
  }
  for (const auto& point : map.mapPoints()) {
    contents.points.push_back(savePoint(*point, sessions.ofPoint(point->id), live));
  }
  const auto by_id = [](const auto& a, const auto& b) { return a.id < b.id; };
  std::sort(contents.keyframes.begin(), contents.keyframes.end(), by_id);
  std::sort(contents.points.begin(), contents.points.end(), by_id);
  return contents;
}

MapSessions restoreMap(const MapFileContents& contents,
                       const std::shared_ptr<const FrameCamera>& camera, Map& map) {
  if (map.numKeyFrames() > 0 || map.numMapPoints() > 0) {
    throw std::logic_error("restoreMap: the map is not empty");
  }
  MapSessions sessions;
  std::unordered_map<std::uint64_t, KeyFrame*> keyframe_of;
  for (const auto& saved : contents.keyframes) {
    const auto keyframe = map.restoreKeyFrame(saved.id, keyFrameContents(saved, camera));
    keyframe_of[saved.id] = keyframe.get();
    sessions.keyframes[saved.id] = saved.session;
    sessions.current = std::max(sessions.current, saved.session + 1);
  }
  for (const auto& saved : contents.keyframes) {
    KeyFrame* keyframe = keyframe_of.at(saved.id);
    for (const auto& [other, weight] : saved.connections) {
      keyframe->addConnection(keyframe_of.at(other), weight);
    }
    if (saved.parent != kNoKeyFrame) keyframe->restoreParent(keyframe_of.at(saved.parent));
  }
  for (const auto& saved : contents.points) {
    KeyFrame* reference = saved.reference_keyframe == kNoKeyFrame
                              ? nullptr
                              : keyframe_of.at(saved.reference_keyframe);
    const auto point = map.restoreMapPoint(saved.id, saved.position, reference);
    point->first_keyframe_id = saved.first_keyframe_id;
    point->normal = saved.normal;
    point->descriptor = cv::Mat(1, 32, CV_8U);
    std::memcpy(point->descriptor.data, saved.descriptor.data(), saved.descriptor.size());
    point->min_distance = saved.min_distance;
    point->max_distance = saved.max_distance;
    point->seen_through = saved.seen_through;
    point->moving_votes = saved.moving_votes;
    point->provisional = saved.provisional;
    point->restored = true;
    for (const auto& [keyframe_id, index] : saved.observations) {
      KeyFrame* keyframe = keyframe_of.at(keyframe_id);
      point->addObservation(keyframe, index);
      keyframe->addMapPoint(point, index);
    }
    sessions.points[saved.id] = saved.session;
    sessions.current = std::max(sessions.current, saved.session + 1);
  }
  return sessions;
}

}  // namespace segslam::map
