#include "segslam/dense/object_map.h"

#include <fmt/format.h>
#include <open3d/geometry/PointCloud.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <tuple>

#include "segslam/core/semantic_class.h"
#include "segslam/dense/open3d_conversion.h"

namespace segslam::dense {

namespace {

using IndexGroups = std::vector<std::vector<std::size_t>>;

// Indices of the points with each label (label 0 left out).
std::map<std::uint8_t, std::vector<std::size_t>> indicesByLabel(const LabelledCloud& cloud) {
  std::map<std::uint8_t, std::vector<std::size_t>> by_label;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.labels[i] != 0) by_label[cloud.labels[i]].push_back(i);
  }
  return by_label;
}

IndexGroups dbscan(const LabelledCloud& cloud, const std::vector<std::size_t>& indices,
                   const ObjectMapOptions& options) {
  if (indices.empty()) return {};
  std::vector<Eigen::Vector3f> points;
  points.reserve(indices.size());
  for (std::size_t i : indices) points.push_back(cloud.points[i]);
  const std::vector<int> cluster_of =
      toOpen3d(points).ClusterDBSCAN(options.cluster_distance, options.core_neighbours);
  IndexGroups clusters;
  for (std::size_t k = 0; k < cluster_of.size(); ++k) {
    if (cluster_of[k] < 0) continue;  // noise
    const auto cluster = static_cast<std::size_t>(cluster_of[k]);
    if (cluster >= clusters.size()) clusters.resize(cluster + 1);
    clusters[cluster].push_back(indices[k]);
  }
  return clusters;
}

std::vector<MapObject> makeObjects(const LabelledCloud& cloud, std::uint8_t label,
                                   const IndexGroups& groups, bool dynamic,
                                   std::size_t min_points) {
  std::vector<MapObject> objects;
  for (const auto& group : groups) {
    if (group.size() < min_points) continue;
    MapObject object;
    object.label = std::string(core::semanticClassName(static_cast<core::SemanticClass>(label)));
    object.dynamic = dynamic;
    object.points = cloud.select(group);
    computeExtent(object);
    objects.push_back(std::move(object));
  }
  std::sort(objects.begin(), objects.end(), [](const MapObject& a, const MapObject& b) {
    return std::make_tuple(b.points.size(), a.centroid.x(), a.centroid.y(), a.centroid.z()) <
           std::make_tuple(a.points.size(), b.centroid.x(), b.centroid.y(), b.centroid.z());
  });
  for (std::size_t i = 0; i < objects.size(); ++i) {
    objects[i].instance = static_cast<int>(i) + 1;
    objects[i].id = fmt::format("{}_{}", objects[i].label, objects[i].instance);
  }
  return objects;
}

}  // namespace

void computeExtent(MapObject& object) {
  const auto& points = object.points.points;
  if (points.empty()) return;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  object.bbox_min = points.front();
  object.bbox_max = points.front();
  for (const auto& p : points) {
    sum += p.cast<double>();
    object.bbox_min = object.bbox_min.cwiseMin(p);
    object.bbox_max = object.bbox_max.cwiseMax(p);
  }
  object.centroid = (sum / static_cast<double>(points.size())).cast<float>();
}

std::vector<MapObject> clusterObjects(const LabelledCloud& cloud, const ObjectMapOptions& options) {
  std::vector<MapObject> objects;
  for (const auto& [label, indices] : indicesByLabel(cloud)) {
    auto label_objects =
        makeObjects(cloud, label, dbscan(cloud, indices, options), false, options.min_points);
    std::move(label_objects.begin(), label_objects.end(), std::back_inserter(objects));
  }
  return objects;
}

std::vector<MapObject> dynamicObjects(const LabelledCloud& cloud, const ObjectMapOptions& options) {
  std::vector<MapObject> objects;
  for (const auto& [label, indices] : indicesByLabel(cloud)) {
    std::map<std::uint16_t, std::vector<std::size_t>> by_instance;
    std::vector<std::size_t> without_instance;
    for (std::size_t i : indices) {
      (cloud.instances[i] != 0 ? by_instance[cloud.instances[i]] : without_instance).push_back(i);
    }
    IndexGroups groups = dbscan(cloud, without_instance, options);
    for (auto& [instance, members] : by_instance) groups.push_back(std::move(members));
    auto label_objects = makeObjects(cloud, label, groups, true, options.min_points);
    std::move(label_objects.begin(), label_objects.end(), std::back_inserter(objects));
  }
  return objects;
}

void numberAfter(const std::vector<MapObject>& first, std::vector<MapObject>& second) {
  std::map<std::string, int> last_instance;
  for (const auto& object : first) {
    last_instance[object.label] = std::max(last_instance[object.label], object.instance);
  }
  for (auto& object : second) {
    object.instance += last_instance[object.label];
    object.id = fmt::format("{}_{}", object.label, object.instance);
  }
}

}  // namespace segslam::dense
