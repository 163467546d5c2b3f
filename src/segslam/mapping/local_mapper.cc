#include "segslam/mapping/local_mapper.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <set>

#include "segslam/mapping/local_window.h"
#include "segslam/mapping/point_fusion.h"
#include "segslam/optim/bundle_adjuster.h"

namespace segslam::mapping {

namespace {

constexpr int kMinObservationsOfRecentPoint = 3;  // RGB-D: a point must be seen from 3 keyframes
// A new point is judged (kept or culled) until this many keyframes after the one that made it.
constexpr std::uint64_t kRecentPointKeyFrames = 3;
constexpr double kMinFoundRatio = 0.25;

}  // namespace

LocalMapper::LocalMapper(map::Map& map, LocalMapperOptions options)
    : map_(map), options_(options) {}

LocalMapper::~LocalMapper() { finish(); }

void LocalMapper::insertKeyFrame(std::shared_ptr<map::KeyFrame> keyframe) {
  {
    std::lock_guard lock(queue_mutex_);
    queue_.push_back(std::move(keyframe));
  }
  queue_changed_.notify_all();
}

bool LocalMapper::isIdle() const {
  std::lock_guard lock(queue_mutex_);
  return queue_.empty() && !busy_;
}

void LocalMapper::addKeyFrameMask(std::uint64_t frame_id, cv::Mat dilated_mask) {
  {
    std::lock_guard lock(queue_mutex_);
    const bool waiting = std::any_of(queue_.begin(), queue_.end(), [&](const auto& keyframe) {
      return keyframe->frame_id == frame_id;
    });
    if (!waiting) return;
    own_masks_[frame_id] = std::move(dilated_mask);
  }
  queue_changed_.notify_all();
}

void LocalMapper::setTrackedFrame(std::uint64_t frame_id) {
  {
    std::lock_guard lock(queue_mutex_);
    tracked_frame_ = frame_id;
  }
  queue_changed_.notify_all();
}

OwnMaskStats LocalMapper::ownMaskStats() const {
  std::lock_guard lock(queue_mutex_);
  OwnMaskStats stats = own_mask_stats_;
  if (stats.keyframes_with_own_mask > 0) {
    stats.mean_wait_frames = own_mask_wait_total_ / stats.keyframes_with_own_mask;
  }
  return stats;
}

bool LocalMapper::keyFrameReady() const {
  std::lock_guard lock(queue_mutex_);
  return frontReady();
}

bool LocalMapper::frontReady() const {
  if (queue_.empty()) return false;
  const std::uint64_t frame_id = queue_.front()->frame_id;
  return stopping_ || options_.own_mask_wait_frames <= 0 || own_masks_.count(frame_id) > 0 ||
         tracked_frame_ >= frame_id + static_cast<std::uint64_t>(options_.own_mask_wait_frames);
}

LocalMapper::ReadyKeyFrame LocalMapper::takeFront() {
  ReadyKeyFrame ready{queue_.front(), cv::Mat()};
  queue_.pop_front();
  if (options_.own_mask_wait_frames <= 0) return ready;
  const auto mask = own_masks_.find(ready.keyframe->frame_id);
  if (mask == own_masks_.end()) {
    ++own_mask_stats_.keyframes_without;
    return ready;
  }
  ready.own_mask = std::move(mask->second);
  own_masks_.erase(mask);
  ++own_mask_stats_.keyframes_with_own_mask;
  own_mask_wait_total_ += static_cast<double>(std::max(tracked_frame_, ready.keyframe->frame_id) -
                                              ready.keyframe->frame_id);
  return ready;
}

std::size_t LocalMapper::queuedKeyFrames() const {
  std::lock_guard lock(queue_mutex_);
  return queue_.size();
}

void LocalMapper::start() {
  stopping_ = false;
  thread_ = std::thread([this] { run(); });
}

void LocalMapper::finish() {
  {
    std::lock_guard lock(queue_mutex_);
    stopping_ = true;
  }
  queue_changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void LocalMapper::pause() {
  std::unique_lock lock(queue_mutex_);
  paused_ = true;
  queue_changed_.wait(lock, [this] { return !busy_; });
}

void LocalMapper::resume() {
  {
    std::lock_guard lock(queue_mutex_);
    paused_ = false;
  }
  queue_changed_.notify_all();
}

void LocalMapper::processQueued() {
  while (auto ready = popKeyFrame()) {
    applyOwnMaskOf(*ready);
    processKeyFrame(ready->keyframe);
  }
}

void LocalMapper::run() {
  while (true) {
    ReadyKeyFrame ready;
    {
      std::unique_lock lock(queue_mutex_);
      queue_changed_.wait(
          lock, [this] { return !paused_ && ((stopping_ && queue_.empty()) || frontReady()); });
      if (queue_.empty()) return;
      ready = takeFront();
      busy_ = true;
    }
    applyOwnMaskOf(ready);
    processKeyFrame(ready.keyframe);
    {
      std::lock_guard lock(queue_mutex_);
      busy_ = false;
    }
    queue_changed_.notify_all();
  }
}

std::optional<LocalMapper::ReadyKeyFrame> LocalMapper::popKeyFrame() {
  std::lock_guard lock(queue_mutex_);
  if (!frontReady()) return std::nullopt;
  return takeFront();
}

void LocalMapper::applyOwnMaskOf(const ReadyKeyFrame& ready) {
  if (ready.own_mask.empty()) return;
  OwnMaskOutcome outcome;
  {
    std::lock_guard lock(map_.mutex);
    if (ready.keyframe->bad) return;
    outcome = applyOwnMask(*ready.keyframe, ready.own_mask, options_.own_mask);
  }
  std::lock_guard lock(queue_mutex_);
  own_mask_stats_.points_culled += outcome.points_culled;
  own_mask_stats_.observations_dropped += outcome.observations_dropped;
}

void LocalMapper::processKeyFrame(const std::shared_ptr<map::KeyFrame>& keyframe) {
  {
    std::lock_guard lock(map_.mutex);
    integrateKeyFrame(*keyframe);
    cullRecentPoints(*keyframe);
    fuseWithNeighbours(*keyframe);
  }
  if (!keyFrameReady() && map_.numKeyFrames() > 2) localBundleAdjustment(*keyframe);
  {
    std::lock_guard lock(map_.mutex);
    if (options_.cull_keyframes) {
      cullRedundantKeyFrames(*keyframe);
      cullOrphanedKeyFrames(*keyframe);
    }
    map_.pruneBadMapPoints();
    if (keyframe->bad) return;
  }
  if (observer_) observer_(keyframe);
}

void LocalMapper::integrateKeyFrame(map::KeyFrame& keyframe) {
  for (const auto& [index, point] : keyframe.validMapPoints()) {
    if (point->first_keyframe_id == keyframe.id) point->provisional = false;
    if (point->reference_keyframe == &keyframe) recent_points_.push_back(point);
    point->updateNormalAndDepth();
    point->updateDescriptor();
  }
  keyframe.updateConnections();
}

void LocalMapper::cullRecentPoints(const map::KeyFrame& keyframe) {
  std::erase_if(recent_points_, [&](const std::shared_ptr<map::MapPoint>& point) {
    if (point->bad) return true;
    const std::uint64_t age = keyframe.id - point->first_keyframe_id;
    if (point->foundRatio() < kMinFoundRatio ||
        (age >= 2 && point->numObservations() < kMinObservationsOfRecentPoint)) {
      point->setBad();
      return true;
    }
    return age >= kRecentPointKeyFrames;
  });
}

void LocalMapper::fuseWithNeighbours(map::KeyFrame& keyframe) {
  std::vector<map::KeyFrame*> targets;
  std::set<std::uint64_t> seen = {keyframe.id};
  for (map::KeyFrame* neighbour : keyframe.bestCovisibles(options_.fusion_neighbours)) {
    if (neighbour->bad || !seen.insert(neighbour->id).second) continue;
    targets.push_back(neighbour);
    for (map::KeyFrame* second : neighbour->bestCovisibles(5)) {
      if (!second->bad && seen.insert(second->id).second) targets.push_back(second);
    }
  }
  std::vector<std::shared_ptr<map::MapPoint>> own_points;
  for (const auto& [index, point] : keyframe.validMapPoints()) own_points.push_back(point);
  for (map::KeyFrame* target : targets) fuseIntoKeyFrame(*target, own_points);

  std::vector<std::shared_ptr<map::MapPoint>> neighbour_points;
  std::set<std::uint64_t> seen_points;
  for (map::KeyFrame* target : targets) {
    for (const auto& [index, point] : target->validMapPoints()) {
      if (seen_points.insert(point->id).second) neighbour_points.push_back(point);
    }
  }
  fuseIntoKeyFrame(keyframe, neighbour_points);
  for (const auto& [index, point] : keyframe.validMapPoints()) {
    point->updateDescriptor();
    point->updateNormalAndDepth();
  }
  keyframe.updateConnections();
}

void LocalMapper::localBundleAdjustment(map::KeyFrame& keyframe) {
  LocalWindow window;
  {
    std::lock_guard lock(map_.mutex);
    if (keyframe.bad) return;
    window = collectLocalWindow(keyframe, static_cast<std::size_t>(options_.ba_max_keyframes));
  }
  const auto start = std::chrono::steady_clock::now();
  optim::BundleAdjustmentOptions ba_options;
  ba_options.iterations_first = options_.ba_first_iterations;
  ba_options.iterations_second = options_.ba_second_iterations;
  const auto result = optim::bundleAdjust(window.problem, ba_options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ba_seconds_ += seconds;
  spdlog::debug(
      "local BA at keyframe {}: {} keyframes ({} fixed), {} points, {} observations, "
      "{} iterations, {:.0f} ms",
      keyframe.id, window.problem.keyframes.size(),
      std::count_if(window.problem.keyframes.begin(), window.problem.keyframes.end(),
                    [](const optim::BaKeyFrame& k) { return k.fixed; }),
      window.problem.points.size(), window.problem.observations.size(), result.iterations,
      1000.0 * seconds);

  std::lock_guard lock(map_.mutex);
  for (std::size_t k = 0; k < window.keyframes.size(); ++k) {
    if (!window.problem.keyframes[k].fixed && !window.keyframes[k]->bad) {
      window.keyframes[k]->T_cw = window.problem.keyframes[k].T_cw;
    }
  }
  for (std::size_t o = 0; o < window.observation_owners.size(); ++o) {
    if (result.observation_inlier[o]) continue;
    auto [observer, point] = window.observation_owners[o];
    if (observer->bad || point->bad || !point->isObservedBy(observer)) continue;
    observer->eraseMapPoint(point);
    point->eraseObservation(observer);
  }
  for (std::size_t p = 0; p < window.points.size(); ++p) {
    const auto& point = window.points[p];
    if (point->bad) continue;
    point->position = window.problem.points[p].position;
    point->updateNormalAndDepth();
  }
}

void LocalMapper::cullRedundantKeyFrames(map::KeyFrame& keyframe) {
  for (map::KeyFrame* candidate : keyframe.covisiblesWithWeight(0)) {
    // Keyframes made after this one still wait in the queue (for their own mask, perhaps):
    // their points are not integrated yet, so they are judged once mapped.
    if (candidate->id == 0 || candidate->bad || candidate->id > keyframe.id) continue;
    if (isRedundant(*candidate, options_.culling) || isCrowded(*candidate, options_.culling)) {
      candidate->setBad();
    }
  }
}

void LocalMapper::cullOrphanedKeyFrames(const map::KeyFrame& keyframe) {
  for (const auto& candidate : map_.keyFrames()) {
    // Until its points are judged, a keyframe's count of them says nothing; keyframes made after
    // this one are not even mapped yet.
    if (candidate->id == 0 || candidate->id + kRecentPointKeyFrames > keyframe.id) continue;
    if (isOrphaned(*candidate, options_.culling)) candidate->setBad();
  }
}

}  // namespace segslam::mapping
