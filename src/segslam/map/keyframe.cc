#include "segslam/map/keyframe.h"

#include <algorithm>

namespace segslam::map {

namespace {
constexpr int kMinCovisibilityWeight = 15;
}

KeyFrame::KeyFrame(std::uint64_t keyframe_id, const Frame& frame)
    : id(keyframe_id),
      frame_id(frame.id),
      timestamp(frame.timestamp),
      camera(frame.camera),
      keypoints(frame.keypoints),
      keypoints_un(frame.keypoints_un),
      depth(frame.depth),
      right_u(frame.right_u),
      descriptors(frame.descriptors),
      dynamic_mask(frame.dynamic_mask),
      image(frame.image),
      grid(frame.grid),
      T_cw(frame.T_cw),
      map_points_(frame.keypoints.size()) {}

Eigen::Vector3d KeyFrame::unproject(std::size_t i) const {
  const auto& kp = keypoints_un[i];
  return T_cw.inverse() * camera->camera.backProject(kp.pt.x, kp.pt.y, depth[i]);
}

optim::RgbdObservation KeyFrame::observation(std::size_t i) const {
  const auto& kp = keypoints_un[i];
  return {{kp.pt.x, kp.pt.y}, right_u[i], camera->levels.inverseSigma2()[kp.octave]};
}

void KeyFrame::addMapPoint(const std::shared_ptr<MapPoint>& point, std::size_t index) {
  map_points_[index] = point;
}

void KeyFrame::eraseMapPoint(std::size_t index) { map_points_[index].reset(); }

void KeyFrame::eraseMapPoint(const MapPoint* point) {
  for (auto& p : map_points_) {
    if (p.get() == point) p.reset();
  }
}

std::vector<std::pair<std::size_t, std::shared_ptr<MapPoint>>> KeyFrame::validMapPoints() const {
  std::vector<std::pair<std::size_t, std::shared_ptr<MapPoint>>> points;
  for (std::size_t i = 0; i < map_points_.size(); ++i) {
    if (map_points_[i] && !map_points_[i]->bad) points.emplace_back(i, map_points_[i]);
  }
  return points;
}

void KeyFrame::updateConnections() {
  std::map<KeyFrame*, int, KeyFrameIdLess> counts;
  for (const auto& p : map_points_) {
    if (!p || p->bad) continue;
    for (const auto& [other, index] : p->observations()) {
      if (other != this && !other->bad) ++counts[other];
    }
  }
  if (counts.empty()) return;
  KeyFrame* best = nullptr;
  int best_weight = 0;
  connections_.clear();
  for (const auto& [other, weight] : counts) {
    if (weight > best_weight) {
      best_weight = weight;
      best = other;
    }
    if (weight >= kMinCovisibilityWeight) {
      connections_[other] = weight;
      other->addConnection(this, weight);
    }
  }
  if (connections_.empty()) {
    connections_[best] = best_weight;
    best->addConnection(this, best_weight);
  }
  sortConnections();
  if (first_connection_ && id != 0) attachToOlderParent();
}

void KeyFrame::attachToOlderParent() {
  // The spanning tree's parent is the strongest covisible keyframe made before this one, so the
  // tree has no cycles: setBad() hands children to their grandparent, and pose resolution and the
  // essential graph follow parents. (A keyframe whose first connections are all to newer ones, as
  // when it had none at first, used to take a newer parent: a cycle, and a self-parent once one
  // of the two went bad.) Without an older covisible it waits for a later update.
  const auto older = std::find_if(ordered_connections_.begin(), ordered_connections_.end(),
                                  [this](const KeyFrame* other) { return other->id < id; });
  if (older == ordered_connections_.end()) return;
  parent = *older;
  parent->children.insert(this);
  first_connection_ = false;
}

void KeyFrame::restoreParent(KeyFrame* tree_parent) {
  parent = tree_parent;
  parent->children.insert(this);
  first_connection_ = false;
}

void KeyFrame::addConnection(KeyFrame* other, int weight) {
  connections_[other] = weight;
  sortConnections();
}

void KeyFrame::eraseConnection(KeyFrame* other) {
  if (connections_.erase(other) > 0) sortConnections();
}

void KeyFrame::sortConnections() {
  std::vector<std::pair<int, KeyFrame*>> sorted;
  for (const auto& [other, weight] : connections_) sorted.emplace_back(weight, other);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  ordered_connections_.clear();
  ordered_weights_.clear();
  for (const auto& [weight, other] : sorted) {
    ordered_connections_.push_back(other);
    ordered_weights_.push_back(weight);
  }
}

std::vector<KeyFrame*> KeyFrame::bestCovisibles(std::size_t n) const {
  const std::size_t count = std::min(n, ordered_connections_.size());
  return {ordered_connections_.begin(), ordered_connections_.begin() + count};
}

std::vector<KeyFrame*> KeyFrame::covisiblesWithWeight(int min_weight) const {
  std::vector<KeyFrame*> result;
  for (std::size_t i = 0; i < ordered_connections_.size(); ++i) {
    if (ordered_weights_[i] < min_weight) break;
    result.push_back(ordered_connections_[i]);
  }
  return result;
}

int KeyFrame::weight(KeyFrame* other) const {
  const auto it = connections_.find(other);
  return it == connections_.end() ? 0 : it->second;
}

void KeyFrame::setBad() {
  if (id == 0 || bad) return;
  for (const auto& [other, weight] : connections_) other->eraseConnection(this);
  for (std::size_t i = 0; i < map_points_.size(); ++i) {
    if (map_points_[i]) map_points_[i]->eraseObservation(this);
  }
  connections_.clear();
  ordered_connections_.clear();
  ordered_weights_.clear();
  // Children are re-attached to this keyframe's parent: the simplest repair that keeps the
  // spanning tree connected (loop correction only needs some tree, not the best one).
  for (KeyFrame* child : children) {
    child->parent = parent;
    if (parent) parent->children.insert(child);
  }
  if (parent) {
    parent->children.erase(this);
    T_c_parent = T_cw * parent->T_cw.inverse();
  }
  children.clear();
  bad = true;
}

void KeyFrame::releaseFeatures() {
  // Swapping with empty containers frees their storage; clear() would keep the capacity.
  std::vector<cv::KeyPoint>().swap(keypoints);
  std::vector<cv::KeyPoint>().swap(keypoints_un);
  std::vector<float>().swap(depth);
  std::vector<float>().swap(right_u);
  descriptors.release();
  dynamic_mask = {};
  image.release();
  grid = KeypointGrid();
  std::vector<std::shared_ptr<MapPoint>>().swap(map_points_);
  released_ = true;
}

}  // namespace segslam::map
