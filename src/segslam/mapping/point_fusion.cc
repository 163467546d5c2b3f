#include "segslam/mapping/point_fusion.h"

#include "segslam/feature/descriptor_distance.h"
#include "segslam/tracking/projection_search.h"

namespace segslam::mapping {

namespace {

bool consistentReprojection(const map::KeyFrame& keyframe, std::size_t i, double u, double v,
                            double right_u) {
  const auto& kp = keyframe.keypoints_un[i];
  const double information = keyframe.camera->levels.inverseSigma2()[kp.octave];
  const double du = kp.pt.x - u;
  const double dv = kp.pt.y - v;
  if (keyframe.right_u[i] >= 0.0f) {
    const double dr = keyframe.right_u[i] - right_u;
    return (du * du + dv * dv + dr * dr) * information < optim::kChi2Stereo;
  }
  return (du * du + dv * dv) * information < optim::kChi2Mono;
}

std::optional<std::size_t> bestKeypointFor(const map::KeyFrame& keyframe,
                                           const map::MapPoint& point, double radius_factor) {
  const Eigen::Vector3d p_c = keyframe.T_cw * point.position;
  if (p_c.z() <= 0.0) return std::nullopt;
  const auto& s = keyframe.camera->stereo;
  const double u = s.fx * p_c.x() / p_c.z() + s.cx;
  const double v = s.fy * p_c.y() / p_c.z() + s.cy;
  if (!keyframe.grid.contains(u, v)) return std::nullopt;
  const Eigen::Vector3d ray = point.position - keyframe.cameraCentre();
  const double dist = ray.norm();
  if (dist < 0.8 * point.min_distance || dist > 1.2 * point.max_distance) return std::nullopt;
  if (ray.dot(point.normal) < 0.5 * dist) return std::nullopt;
  const auto& levels = keyframe.camera->levels;
  const int level = point.predictLevel(dist, levels);
  const double radius = radius_factor * levels.scales()[level];
  const double right_u = u - s.bf / p_c.z();
  int best_distance = 256;
  std::optional<std::size_t> best;
  for (std::size_t i :
       keyframe.grid.featuresInArea(keyframe.keypoints_un, u, v, radius, level - 1, level)) {
    if (!consistentReprojection(keyframe, i, u, v, right_u)) continue;
    const int d = feature::descriptorDistance(point.descriptor.ptr<std::uint8_t>(),
                                              keyframe.descriptors.ptr<std::uint8_t>(i));
    if (d < best_distance) {
      best_distance = d;
      best = i;
    }
  }
  if (best_distance > tracking::kMaxDistanceLow) return std::nullopt;
  return best;
}

// Of two points found to be one, the restored one survives (a loaded map keeps its points),
// else the one seen from more keyframes.
bool survivesMerge(const map::MapPoint& existing, const map::MapPoint& point) {
  if (existing.restored != point.restored) return existing.restored;
  return existing.numObservations() > point.numObservations();
}

}  // namespace

int fuseIntoKeyFrame(map::KeyFrame& keyframe,
                     const std::vector<std::shared_ptr<map::MapPoint>>& points,
                     double radius_factor) {
  int fused = 0;
  for (const auto& point : points) {
    if (!point || point->bad || point->isObservedBy(&keyframe)) continue;
    const auto index = bestKeypointFor(keyframe, *point, radius_factor);
    if (!index) continue;
    const auto existing = keyframe.mapPoints()[*index];
    if (existing && !existing->bad) {
      // Two restored points stay as their session left them: merging loses a loaded point.
      if (existing->restored && point->restored) continue;
      if (survivesMerge(*existing, *point)) {
        point->replaceWith(existing);
      } else {
        existing->replaceWith(point);
      }
    } else {
      point->addObservation(&keyframe, *index);
      keyframe.addMapPoint(point, *index);
    }
    ++fused;
  }
  return fused;
}

}  // namespace segslam::mapping
