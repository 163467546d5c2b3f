#include "segslam/mapping/keyframe_culling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "segslam/map/map_point.h"

namespace segslam::mapping {
namespace {

constexpr int kRedundantObservers = 3;

// Whether at least three other keyframes see the point at the keyframe's scale or finer.
bool seenAtFinerScale(const map::KeyFrame& keyframe, const map::MapPoint& point, int level) {
  if (point.numObservations() <= kRedundantObservers) return false;
  int observers = 0;
  for (const auto& [observer, index] : point.observations()) {
    if (observer == &keyframe) continue;
    if (observer->keypoints_un[index].octave <= level + 1) ++observers;
    if (observers >= kRedundantObservers) return true;
  }
  return false;
}

}  // namespace

bool isRedundant(const map::KeyFrame& keyframe, const KeyFrameCullingOptions& options) {
  int close_points = 0;
  int redundant = 0;
  const double close_depth = keyframe.camera->close_depth_m;
  for (const auto& [index, point] : keyframe.validMapPoints()) {
    if (keyframe.depth[index] <= 0.0f || keyframe.depth[index] > close_depth) continue;
    ++close_points;
    if (seenAtFinerScale(keyframe, *point, keyframe.keypoints_un[index].octave)) ++redundant;
  }
  return close_points > 0 && redundant > options.redundant_share * close_points;
}

bool isCrowded(const map::KeyFrame& keyframe, const KeyFrameCullingOptions& options) {
  if (options.crowded_covisible_share <= 0.0) return false;
  const std::size_t points = keyframe.validMapPoints().size();
  const int min_weight = std::max(1, static_cast<int>(std::ceil(options.crowded_covisible_share *
                                                                static_cast<double>(points))));
  const geometry::Pose T_wc = keyframe.T_cw.inverse();
  const double min_cos_angle = std::cos(options.crowded_angle_deg * std::numbers::pi / 180.0);
  for (const map::KeyFrame* neighbour : keyframe.covisiblesWithWeight(min_weight)) {
    if (neighbour->bad || neighbour->validMapPoints().size() < points) continue;
    const geometry::Pose T_wn = neighbour->T_cw.inverse();
    if ((T_wn.translation() - T_wc.translation()).norm() > options.crowded_distance_m) continue;
    if (T_wn.linear().col(2).dot(T_wc.linear().col(2)) >= min_cos_angle) return true;
  }
  return false;
}

bool isOrphaned(const map::KeyFrame& keyframe, const KeyFrameCullingOptions& options) {
  return keyframe.validMapPoints().size() < static_cast<std::size_t>(options.orphaned_below_points);
}

}  // namespace segslam::mapping
