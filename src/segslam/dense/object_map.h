#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

// A box around an object along its principal axes: centre, edge lengths along the columns of
// `axes` (a rotation, world from box).
struct OrientedBox {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  Eigen::Vector3f extent = Eigen::Vector3f::Zero();
  Eigen::Matrix3f axes = Eigen::Matrix3f::Identity();
};

// One object of the map: a real object seen from several keyframes, with what a user picking it
// needs.
struct MapObject {
  std::string id;  // "<label>_<instance>", e.g. "chair_1"
  std::string label;
  int instance = 0;  // 1, 2, ... per label, largest object first (static before dynamic)
  bool dynamic = false;
  double confidence = 0.0;  // share of the keyframes that saw it that gave it its label
  int keyframes = 0;        // keyframes that saw it
  LabelledCloud points;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  Eigen::Vector3f bbox_min = Eigen::Vector3f::Zero();
  Eigen::Vector3f bbox_max = Eigen::Vector3f::Zero();
  OrientedBox box;
};

// Fills centroid, axis-aligned bounds and the oriented box from the points.
void computeExtent(MapObject& object);

// Sorts the objects (static before dynamic, then by label id, then largest first) and numbers
// them per label in that order, so that ids are unique and do not depend on point order.
void numberObjects(std::vector<MapObject>& objects);

}  // namespace segslam::dense
