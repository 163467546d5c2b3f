#include "segslam/dense/object_map.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

#include "segslam/core/semantic_class.h"

namespace segslam::dense {

namespace {

// Principal axes of the points, as a right-handed rotation.
Eigen::Matrix3f principalAxes(const std::vector<Eigen::Vector3f>& points,
                              const Eigen::Vector3d& mean) {
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector3d d = p.cast<double>() - mean;
    covariance += d * d.transpose();
  }
  Eigen::Matrix3d axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors();
  axes.col(0) = axes.col(1).cross(axes.col(2));
  return axes.cast<float>();
}

OrientedBox orientedBox(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3d& mean) {
  OrientedBox box;
  box.axes = principalAxes(points, mean);
  Eigen::Vector3f low = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f high = -low;
  for (const auto& p : points) {
    const Eigen::Vector3f local = box.axes.transpose() * p;
    low = low.cwiseMin(local);
    high = high.cwiseMax(local);
  }
  box.extent = high - low;
  box.centre = box.axes * (0.5f * (low + high));
  return box;
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
  const Eigen::Vector3d mean = sum / static_cast<double>(points.size());
  object.centroid = mean.cast<float>();
  object.box = orientedBox(points, mean);
}

void numberObjects(std::vector<MapObject>& objects) {
  const auto label_id = [](const MapObject& object) {
    return static_cast<int>(
        core::semanticClassFromName(object.label).value_or(static_cast<core::SemanticClass>(255)));
  };
  std::sort(objects.begin(), objects.end(), [&](const MapObject& a, const MapObject& b) {
    return std::make_tuple(a.dynamic, label_id(a), b.points.size(), a.centroid.x(), a.centroid.y(),
                           a.centroid.z()) < std::make_tuple(b.dynamic, label_id(b),
                                                             a.points.size(), b.centroid.x(),
                                                             b.centroid.y(), b.centroid.z());
  });
  std::map<std::string, int> count;
  for (MapObject& object : objects) {
    object.instance = ++count[object.label];
    object.id = fmt::format("{}_{}", object.label, object.instance);
  }
}

}  // namespace segslam::dense
