#include "segslam/map/map_point.h"

#include <algorithm>
#include <cmath>

#include "segslam/feature/descriptor_distance.h"
#include "segslam/map/keyframe.h"

namespace segslam::map {

bool KeyFrameIdLess::operator()(const KeyFrame* a, const KeyFrame* b) const {
  return a->id < b->id;
}

MapPoint::MapPoint(std::uint64_t point_id, const Eigen::Vector3d& p, KeyFrame* reference)
    : id(point_id),
      first_keyframe_id(reference ? reference->id : 0),
      position(p),
      reference_keyframe(reference) {}

void MapPoint::addObservation(KeyFrame* keyframe, std::size_t keypoint_index) {
  observations_[keyframe] = keypoint_index;
}

void MapPoint::eraseObservation(KeyFrame* keyframe) {
  if (observations_.erase(keyframe) == 0) return;
  if (reference_keyframe == keyframe && !observations_.empty()) {
    reference_keyframe = observations_.begin()->first;
  }
  // A point seen from fewer than two keyframes carries no multi-view constraint any more; a
  // restored point was verified by its session and stays while a keyframe still holds it.
  if (observations_.size() < (restored ? 1u : 2u)) setBad();
}

int MapPoint::numObservations() const { return static_cast<int>(observations_.size()); }

bool MapPoint::isObservedBy(const KeyFrame* keyframe) const {
  return observations_.count(const_cast<KeyFrame*>(keyframe)) > 0;
}

void MapPoint::updateDescriptor() {
  std::vector<const std::uint8_t*> descriptors;
  for (const auto& [keyframe, index] : observations_) {
    if (!keyframe->bad) descriptors.push_back(keyframe->descriptors.ptr<std::uint8_t>(index));
  }
  if (descriptors.empty()) return;
  std::size_t best = 0;
  int best_median = INT32_MAX;
  std::vector<int> distances(descriptors.size());
  for (std::size_t i = 0; i < descriptors.size(); ++i) {
    for (std::size_t j = 0; j < descriptors.size(); ++j) {
      distances[j] = feature::descriptorDistance(descriptors[i], descriptors[j]);
    }
    std::nth_element(distances.begin(), distances.begin() + (distances.size() - 1) / 2,
                     distances.end());
    const int median = distances[(distances.size() - 1) / 2];
    if (median < best_median) {
      best_median = median;
      best = i;
    }
  }
  descriptor = cv::Mat(1, 32, CV_8U, const_cast<std::uint8_t*>(descriptors[best])).clone();
}

void MapPoint::updateNormalAndDepth() {
  if (observations_.empty() || reference_keyframe == nullptr) return;
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  for (const auto& [keyframe, index] : observations_) {
    normal_sum += (position - keyframe->cameraCentre()).normalized();
  }
  normal = normal_sum.normalized();
  const auto it = observations_.find(reference_keyframe);
  if (it == observations_.end()) return;
  const double distance = (position - reference_keyframe->cameraCentre()).norm();
  const auto& levels = reference_keyframe->camera->levels;
  const int level = reference_keyframe->keypoints_un[it->second].octave;
  max_distance = distance * levels.scales()[level];
  min_distance = max_distance / levels.scales()[levels.numLevels() - 1];
}

int MapPoint::predictLevel(double distance, const feature::ScaleLevels& levels) const {
  const double ratio = max_distance / distance;
  const int level = static_cast<int>(std::ceil(std::log(ratio) / std::log(levels.factor())));
  return std::clamp(level, 0, levels.numLevels() - 1);
}

void MapPoint::setBad() {
  if (bad) return;
  bad = true;
  auto observations = std::move(observations_);
  observations_.clear();
  for (const auto& [keyframe, index] : observations) keyframe->eraseMapPoint(index);
}

void MapPoint::replaceWith(const std::shared_ptr<MapPoint>& other) {
  if (other.get() == this || bad) return;
  auto observations = std::move(observations_);
  observations_.clear();
  bad = true;
  replaced_by = other;
  for (const auto& [keyframe, index] : observations) {
    if (other->isObservedBy(keyframe)) {
      keyframe->eraseMapPoint(index);
    } else {
      keyframe->addMapPoint(other, index);
      other->addObservation(keyframe, index);
    }
  }
  other->increaseFound(found_);
  other->increaseVisible(visible_);
  other->updateDescriptor();
}

}  // namespace segslam::map
