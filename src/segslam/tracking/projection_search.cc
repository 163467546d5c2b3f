#include "segslam/tracking/projection_search.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "segslam/feature/descriptor_distance.h"

namespace segslam::tracking {

namespace {

constexpr int kRotationBins = 30;

int distance(const cv::Mat& a, int row_a, const cv::Mat& b, int row_b) {
  return feature::descriptorDistance(a.ptr<std::uint8_t>(row_a), b.ptr<std::uint8_t>(row_b));
}

float angleDifference(const cv::KeyPoint& a, const cv::KeyPoint& b) {
  float diff = a.angle - b.angle;
  if (diff < 0.0f) diff += 360.0f;
  return diff;
}

bool isFree(const map::Frame& frame, std::size_t i) {
  const auto& p = frame.map_points[i];
  return !p || p->bad || p->numObservations() == 0;
}

struct BestCandidate {
  int best_distance = 256;
  int second_distance = 256;
  int best_level = -1;
  int second_level = -1;
  std::size_t best_index = SIZE_MAX;
};

BestCandidate bestAmong(const map::Frame& frame, const std::vector<std::size_t>& candidates,
                        const cv::Mat& descriptor, double right_u, double max_right_error,
                        bool require_free) {
  BestCandidate best;
  for (std::size_t i : candidates) {
    if (require_free && !isFree(frame, i)) continue;
    if (right_u >= 0.0 && frame.right_u[i] >= 0.0 &&
        std::abs(right_u - frame.right_u[i]) > max_right_error) {
      continue;
    }
    const int d = distance(descriptor, 0, frame.descriptors, static_cast<int>(i));
    const int level = frame.keypoints_un[i].octave;
    if (d < best.best_distance) {
      best.second_distance = best.best_distance;
      best.second_level = best.best_level;
      best.best_distance = d;
      best.best_level = level;
      best.best_index = i;
    } else if (d < best.second_distance) {
      best.second_distance = d;
      best.second_level = level;
    }
  }
  return best;
}

}  // namespace

std::optional<ProjectedPoint> projectIntoFrame(const std::shared_ptr<map::MapPoint>& point,
                                               const map::Frame& frame, double min_view_cosine) {
  const Eigen::Vector3d p_c = frame.T_cw * point->position;
  if (p_c.z() <= 0.0) return std::nullopt;
  const auto& stereo = frame.camera->stereo;
  const double u = stereo.fx * p_c.x() / p_c.z() + stereo.cx;
  const double v = stereo.fy * p_c.y() / p_c.z() + stereo.cy;
  if (!frame.grid.contains(u, v) || frame.isDynamicAt(u, v)) return std::nullopt;
  const Eigen::Vector3d ray = point->position - frame.cameraCentre();
  const double dist = ray.norm();
  if (dist < 0.8 * point->min_distance || dist > 1.2 * point->max_distance) return std::nullopt;
  const double view_cosine = ray.dot(point->normal) / dist;
  if (view_cosine < min_view_cosine) return std::nullopt;
  ProjectedPoint projected;
  projected.point = point;
  projected.u = u;
  projected.v = v;
  projected.right_u = u - stereo.bf / p_c.z();
  projected.predicted_level = point->predictLevel(dist, frame.camera->levels);
  projected.view_cosine = view_cosine;
  return projected;
}

int searchLocalPoints(map::Frame& frame, const std::vector<ProjectedPoint>& projections,
                      double radius_factor) {
  int matches = 0;
  const auto& levels = frame.camera->levels;
  for (const auto& projected : projections) {
    // Points seen head-on need a smaller window than points seen at an angle.
    const double view_factor = projected.view_cosine > 0.998 ? 2.5 : 4.0;
    const double radius = radius_factor * view_factor * levels.scales()[projected.predicted_level];
    const auto candidates =
        frame.grid.featuresInArea(frame.keypoints_un, projected.u, projected.v, radius,
                                  projected.predicted_level - 1, projected.predicted_level);
    if (candidates.empty()) continue;
    const auto best =
        bestAmong(frame, candidates, projected.point->descriptor, projected.right_u, radius, true);
    if (best.best_distance > kMaxDistanceHigh) continue;
    if (best.best_level == best.second_level && best.best_distance > 0.8 * best.second_distance) {
      continue;
    }
    frame.map_points[best.best_index] = projected.point;
    frame.outlier[best.best_index] = false;
    ++matches;
  }
  return matches;
}

std::vector<std::size_t> rotationInconsistentMatches(const std::vector<float>& angle_differences) {
  std::array<std::vector<std::size_t>, kRotationBins> histogram;
  for (std::size_t i = 0; i < angle_differences.size(); ++i) {
    int bin = static_cast<int>(std::lround(angle_differences[i] * kRotationBins / 360.0f));
    if (bin == kRotationBins) bin = 0;
    histogram[std::clamp(bin, 0, kRotationBins - 1)].push_back(i);
  }
  std::array<int, kRotationBins> order{};
  for (int b = 0; b < kRotationBins; ++b) order[b] = b;
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return histogram[a].size() > histogram[b].size(); });
  // Secondary bins only count when they hold a real share of the matches.
  const std::size_t top = histogram[order[0]].size();
  std::vector<std::size_t> dropped;
  for (int rank = 0; rank < kRotationBins; ++rank) {
    const auto& bin = histogram[order[rank]];
    const bool keep = rank == 0 || (rank < 3 && bin.size() >= top / 10);
    if (!keep) dropped.insert(dropped.end(), bin.begin(), bin.end());
  }
  return dropped;
}

int searchFromLastFrame(map::Frame& current, const map::Frame& last, double radius) {
  const auto& levels = current.camera->levels;
  std::vector<std::size_t> matched_keypoints;
  std::vector<float> angle_differences;
  for (std::size_t j = 0; j < last.size(); ++j) {
    const auto& point = last.map_points[j];
    if (!point || point->bad || last.outlier[j]) continue;
    const Eigen::Vector3d p_c = current.T_cw * point->position;
    if (p_c.z() <= 0.0) continue;
    const auto& stereo = current.camera->stereo;
    const double u = stereo.fx * p_c.x() / p_c.z() + stereo.cx;
    const double v = stereo.fy * p_c.y() / p_c.z() + stereo.cy;
    if (!current.grid.contains(u, v) || current.isDynamicAt(u, v)) continue;
    const int level = last.keypoints_un[j].octave;
    const double window = radius * levels.scales()[level];
    const auto candidates = current.grid.featuresInArea(current.keypoints_un, u, v, window,
                                                        std::max(0, level - 1), level + 1);
    if (candidates.empty()) continue;
    const double right_u = u - stereo.bf / p_c.z();
    const auto best = bestAmong(current, candidates, point->descriptor, right_u, window, true);
    if (best.best_distance > kMaxDistanceHigh) continue;
    current.map_points[best.best_index] = point;
    current.outlier[best.best_index] = false;
    matched_keypoints.push_back(best.best_index);
    angle_differences.push_back(
        angleDifference(last.keypoints[j], current.keypoints[best.best_index]));
  }
  const auto dropped = rotationInconsistentMatches(angle_differences);
  for (std::size_t m : dropped) current.map_points[matched_keypoints[m]].reset();
  return static_cast<int>(matched_keypoints.size() - dropped.size());
}

int searchByDescriptors(map::Frame& frame, const map::KeyFrame& keyframe, double ratio) {
  std::vector<std::size_t> matched_keypoints;
  std::vector<float> angle_differences;
  std::vector<int> best_for_keypoint(frame.size(), 256);
  for (const auto& [kf_index, point] : keyframe.validMapPoints()) {
    int best = 256;
    int second = 256;
    std::size_t best_index = SIZE_MAX;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const int d = distance(keyframe.descriptors, static_cast<int>(kf_index), frame.descriptors,
                             static_cast<int>(i));
      if (d < best) {
        second = best;
        best = d;
        best_index = i;
      } else if (d < second) {
        second = d;
      }
    }
    if (best > kMaxDistanceLow || best >= ratio * second) continue;
    if (best >= best_for_keypoint[best_index]) continue;
    best_for_keypoint[best_index] = best;
    frame.map_points[best_index] = point;
    matched_keypoints.push_back(best_index);
    angle_differences.push_back(
        angleDifference(keyframe.keypoints[kf_index], frame.keypoints[best_index]));
  }
  const auto dropped = rotationInconsistentMatches(angle_differences);
  for (std::size_t m : dropped) frame.map_points[matched_keypoints[m]].reset();
  return static_cast<int>(matched_keypoints.size() - dropped.size());
}

}  // namespace segslam::tracking
