#include "segslam/dense/object_map_builder.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <unordered_map>

#include "segslam/core/semantic_class.h"
#include "segslam/dense/voxel_key.h"

namespace segslam::dense {

namespace {

std::string labelName(std::uint8_t label) {
  return std::string(core::semanticClassName(static_cast<core::SemanticClass>(label)));
}

struct CellOwner {
  std::size_t object = 0;
  std::uint8_t label = 0;
  int keyframes = 0;
};

// The object a point of `label` in a cell goes to: the one of its label that saw the cell in the
// most keyframes, else (a view that labelled the point wrongly) the one of any label that did.
const CellOwner* ownerOf(const std::vector<CellOwner>& owners, std::uint8_t label) {
  const CellOwner* best_any = nullptr;
  const CellOwner* best_same = nullptr;
  for (const CellOwner& owner : owners) {
    if (!best_any || owner.keyframes > best_any->keyframes) best_any = &owner;
    if (owner.label == label && (!best_same || owner.keyframes > best_same->keyframes)) {
      best_same = &owner;
    }
  }
  return best_same ? best_same : best_any;
}

}  // namespace

ObjectMapBuilder::ObjectMapBuilder(const core::Camera& camera, double max_depth,
                                   ObjectMapOptions options)
    : camera_(camera),
      max_depth_(max_depth),
      options_(options),
      associator_(options.cell_size, options.association),
      tracker_(options.dynamic) {}

void ObjectMapBuilder::addKeyFrame(std::uint64_t id, double timestamp,
                                   const Eigen::Isometry3d& T_wc,
                                   const LabelledCloud& static_points,
                                   const LabelledCloud& dynamic_points) {
  T_cw_.push_back(T_wc.inverse());
  associator_.addKeyFrame(
      id, segmentByLabel(static_points, options_.cell_size, options_.min_segment_points));
  const std::vector<LabelSegment> dynamic_segments =
      segmentByLabel(dynamic_points, options_.dynamic.cell_size, options_.min_segment_points);
  tracker_.addKeyFrame(
      id, timestamp, dynamic_points, dynamic_segments,
      KeyFrameDepthView(camera_, T_cw_.back(), static_points, dynamic_points, dynamic_segments));
}

int ObjectMapBuilder::keyframesSeeing(const Eigen::Vector3f& point) const {
  int seeing = 0;
  for (const Eigen::Isometry3d& T_cw : T_cw_) {
    const Eigen::Vector3d p = T_cw * point.cast<double>();
    if (!(p.z() > 0.0) || p.z() > max_depth_) continue;
    const double u = camera_.fx * p.x() / p.z() + camera_.cx;
    const double v = camera_.fy * p.y() / p.z() + camera_.cy;
    if (u >= 0.0 && v >= 0.0 && u < camera_.width && v < camera_.height) ++seeing;
  }
  return seeing;
}

std::vector<MapObject> ObjectMapBuilder::staticObjects(const LabelledCloud& static_map) const {
  std::vector<ObservedObject> observed = associator_.objects();
  std::erase_if(observed, [this](const ObservedObject& object) {
    const int seen = static_cast<int>(object.keyframes.size());
    const int seeing = std::max(keyframesSeeing(object.centroid()), seen);
    return seen < options_.min_keyframes || seen < options_.min_seen_share * seeing;
  });
  std::unordered_map<std::uint64_t, std::vector<CellOwner>> owners;
  for (std::size_t k = 0; k < observed.size(); ++k) {
    for (const auto& [cell, keyframes] : observed[k].cell_counts) {
      owners[cell].push_back({k, observed[k].label(), keyframes});
    }
  }
  std::vector<std::vector<std::size_t>> members(observed.size());
  for (std::size_t i = 0; i < static_map.size(); ++i) {
    if (!isObjectLabel(static_map.labels[i])) continue;
    const auto it = owners.find(voxelKey(static_map.points[i], options_.cell_size));
    if (it != owners.end()) members[ownerOf(it->second, static_map.labels[i])->object].push_back(i);
  }
  std::vector<MapObject> objects;
  for (std::size_t k = 0; k < observed.size(); ++k) {
    if (members[k].size() < options_.min_points) continue;
    MapObject object;
    object.label = labelName(observed[k].label());
    object.confidence = observed[k].confidence();
    object.keyframes = static_cast<int>(observed[k].keyframes.size());
    object.points = static_map.select(members[k]);
    computeExtent(object);
    objects.push_back(std::move(object));
  }
  return objects;
}

double ObjectMapBuilder::shareOnStatic(
    const LabelledCloud& points, const std::unordered_set<std::uint64_t>& static_cells) const {
  if (points.empty()) return 0.0;
  std::size_t on_static = 0;
  for (const Eigen::Vector3f& point : points.points) {
    const Eigen::Vector3i cell = cellOf(point, options_.cell_size);
    bool near = false;
    for (int dx = -1; dx <= 1 && !near; ++dx) {
      for (int dy = -1; dy <= 1 && !near; ++dy) {
        for (int dz = -1; dz <= 1 && !near; ++dz) {
          near = static_cells.contains(packCell(cell + Eigen::Vector3i(dx, dy, dz)));
        }
      }
    }
    if (near) ++on_static;
  }
  return static_cast<double>(on_static) / static_cast<double>(points.size());
}

std::vector<MapObject> ObjectMapBuilder::dynamicObjects(const LabelledCloud& static_map,
                                                        double voxel_size) const {
  std::unordered_set<std::uint64_t> static_cells;
  for (const Eigen::Vector3f& point : static_map.points) {
    static_cells.insert(voxelKey(point, options_.cell_size));
  }
  std::vector<MapObject> objects;
  for (const DynamicTrack& track : tracker_.tracks()) {
    if (static_cast<double>(track.points.size()) <
        options_.min_dynamic_share * static_cast<double>(track.keyframe_points)) {
      continue;
    }
    // A walker seen only where they passed to and fro moves their centroids little; a view of a
    // place they left, or of a place empty before they stood there, says that they walked. For a
    // person seen whole (min_reach_points) that holds even when one keyframe saw them: the second
    // of two people pacing one line is in view alone only where the first could have walked, and
    // is tracked apart only in the view that shows both. Other single views show neither that
    // something moved nor that it sat.
    const bool is_person = track.label == static_cast<std::uint8_t>(core::SemanticClass::kPerson);
    const bool walked = (track.keyframes.size() >= 2 && (track.travelled >= options_.min_travel ||
                                                         track.left_a_place || track.arrived)) ||
                        (is_person && (track.arrived || track.left_a_place) &&
                         track.points.size() >= options_.dynamic.min_reach_points);
    const bool sat_still =
        is_person && static_cast<int>(track.keyframes.size()) >= options_.min_keyframes;
    if (!walked && !sat_still) continue;
    MapObject object;
    object.points = voxelDownsample(track.points, voxel_size);
    const double on_static = shareOnStatic(object.points, static_cells);
    // A person is never a static thing: far walkers' points lie by the back wall, or where the
    // mask missed them in other keyframes (s14: 0.99).
    const bool moved = walked && (is_person || on_static < options_.max_on_static_share);
    spdlog::debug(
        "dynamic objects: {} track of {} keyframes: travelled {:.2f} m, left a place {}, "
        "arrived {}, on the static map {:.2f}: {}",
        labelName(track.label), track.keyframes.size(), track.travelled, track.left_a_place,
        track.arrived, on_static, moved ? "moving" : (sat_still ? "still" : "no object"));
    if ((!moved && !sat_still) || object.points.size() < options_.min_points) continue;
    object.label = labelName(track.label);
    object.dynamic = moved;
    object.confidence = 1.0;  // a track keeps one label
    object.keyframes = static_cast<int>(track.keyframes.size());
    computeExtent(object);
    objects.push_back(std::move(object));
  }
  return objects;
}

std::vector<MapObject> ObjectMapBuilder::objects(const LabelledCloud& static_map,
                                                 double voxel_size) const {
  std::vector<MapObject> objects = staticObjects(static_map);
  std::vector<MapObject> dynamic = dynamicObjects(static_map, voxel_size);
  std::move(dynamic.begin(), dynamic.end(), std::back_inserter(objects));
  numberObjects(objects);
  return objects;
}

}  // namespace segslam::dense
