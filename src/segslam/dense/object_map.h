#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

// One object instance of the map: the points of one label that hang together.
struct MapObject {
  std::string id;  // "<label>_<instance>", e.g. "chair_1"
  std::string label;
  int instance = 0;  // 1, 2, ... per label, largest object first
  bool dynamic = false;
  LabelledCloud points;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  Eigen::Vector3f bbox_min = Eigen::Vector3f::Zero();
  Eigen::Vector3f bbox_max = Eigen::Vector3f::Zero();
};

struct ObjectMapOptions {
  // Points of a label closer than this are in the same object (metres): a few voxels.
  double cluster_distance = 0.03;
  // DBSCAN's density: a point with this many neighbours within cluster_distance grows a
  // cluster. A surface sampled at 1 cm has about 28 within 3 cm.
  std::size_t core_neighbours = 10;
  // Smaller clusters are fragments or noise, not objects.
  std::size_t min_points = 100;
};

// Splits the labelled points of a static map into objects: per label (label 0, unknown, is
// skipped), Open3D's DBSCAN with eps = cluster_distance, so that an object seen from several
// keyframes is one instance wherever its points overlap. Instances are numbered per label by
// decreasing size (ties by centroid), so the numbering does not depend on the point order.
std::vector<MapObject> clusterObjects(const LabelledCloud& cloud, const ObjectMapOptions& options);

// The dynamic layer's objects: one per (label, dataset instance id) pair, as a person tracked by
// the segmentation is one object however far it walked; points without an instance id are
// clustered like static ones. Marked dynamic.
std::vector<MapObject> dynamicObjects(const LabelledCloud& cloud, const ObjectMapOptions& options);

// Renumbers `second` after `first`, label by label (person_1 static, person_2 dynamic), so that
// the ids of both lists together are unique.
void numberAfter(const std::vector<MapObject>& first, std::vector<MapObject>& second);

// Fills centroid and bounding box from the points.
void computeExtent(MapObject& object);

}  // namespace segslam::dense
