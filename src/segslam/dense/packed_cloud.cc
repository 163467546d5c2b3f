#include "segslam/dense/packed_cloud.h"

#include <cmath>
#include <limits>

namespace segslam::dense {

namespace {

constexpr float kMillimetresPerMetre = 1000.0F;

bool packable(const Eigen::Vector3f& point) {
  constexpr float kMostMm = std::numeric_limits<std::int16_t>::max();
  return (point.array().abs() * kMillimetresPerMetre).maxCoeff() <= kMostMm;
}

std::int16_t millimetres(float metres) {
  return static_cast<std::int16_t>(std::lround(metres * kMillimetresPerMetre));
}

}  // namespace

PackedCloud::PackedCloud(const LabelledCloud& cloud) {
  points_.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f& p = cloud.points[i];
    if (!p.allFinite() || !packable(p)) continue;
    points_.push_back({{millimetres(p.x()), millimetres(p.y()), millimetres(p.z())},
                       cloud.colours[i],
                       cloud.labels[i],
                       cloud.instances[i]});
  }
  points_.shrink_to_fit();
}

LabelledCloud PackedCloud::unpacked() const {
  LabelledCloud cloud;
  cloud.reserve(points_.size());
  for (const Point& p : points_) {
    const Eigen::Vector3f metres(p.mm[0], p.mm[1], p.mm[2]);
    cloud.add(metres / kMillimetresPerMetre, p.colour, p.label, p.instance);
  }
  return cloud;
}

PackedKeyFrameCloud::PackedKeyFrameCloud(const KeyFrameCloud& cloud)
    : static_points(cloud.static_points),
      dynamic_points(cloud.dynamic_points),
      folded_points(cloud.folded_points) {}

KeyFrameCloud PackedKeyFrameCloud::unpacked() const {
  return {static_points.unpacked(), dynamic_points.unpacked(), folded_points.unpacked()};
}

}  // namespace segslam::dense
