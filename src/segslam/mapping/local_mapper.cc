#include "segslam/mapping/local_mapper.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <set>

#include "segslam/mapping/point_fusion.h"
#include "segslam/optim/bundle_adjuster.h"

namespace segslam::mapping {

namespace {

constexpr int kMinObservationsOfRecentPoint = 3;  // RGB-D: a point must be seen from 3 keyframes
constexpr double kMinFoundRatio = 0.25;

// Keyframes and points of one local bundle adjustment, with the indices the solver uses.
struct LocalWindow {
  std::vector<map::KeyFrame*> keyframes;  // optimised first, then fixed
  std::vector<std::shared_ptr<map::MapPoint>> points;
  optim::BundleAdjustmentProblem problem;
  std::vector<std::pair<map::KeyFrame*, map::MapPoint*>> observation_owners;
};

LocalWindow collectLocalWindow(map::KeyFrame& keyframe, std::size_t max_keyframes) {
  LocalWindow window;
  const std::uint64_t tag = keyframe.id;
  keyframe.ba_local_keyframe = tag;
  std::vector<map::KeyFrame*> local = {&keyframe};
  for (map::KeyFrame* neighbour : keyframe.covisiblesWithWeight(0)) {
    if (local.size() >= max_keyframes) break;
    if (neighbour->bad) continue;
    neighbour->ba_local_keyframe = tag;
    local.push_back(neighbour);
  }
  std::set<std::uint64_t> seen_points;
  for (map::KeyFrame* k : local) {
    for (const auto& [index, point] : k->validMapPoints()) {
      if (seen_points.insert(point->id).second) window.points.push_back(point);
    }
  }
  std::vector<map::KeyFrame*> fixed;
  for (const auto& point : window.points) {
    for (const auto& [observer, index] : point->observations()) {
      if (observer->bad || observer->ba_local_keyframe == tag ||
          observer->ba_fixed_keyframe == tag) {
        continue;
      }
      observer->ba_fixed_keyframe = tag;
      fixed.push_back(observer);
    }
  }
  window.keyframes = local;
  window.keyframes.insert(window.keyframes.end(), fixed.begin(), fixed.end());
  return window;
}

void buildProblem(LocalWindow& window) {
  auto& problem = window.problem;
  problem.intrinsics = window.keyframes.front()->camera->stereo;
  std::map<const map::KeyFrame*, std::size_t> keyframe_index;
  for (std::size_t k = 0; k < window.keyframes.size(); ++k) {
    map::KeyFrame* keyframe = window.keyframes[k];
    const bool fixed =
        keyframe->id == 0 || keyframe->ba_local_keyframe != window.keyframes.front()->id;
    problem.keyframes.push_back({keyframe->id, keyframe->T_cw, fixed});
    keyframe_index[keyframe] = k;
  }
  for (std::size_t p = 0; p < window.points.size(); ++p) {
    const auto& point = window.points[p];
    problem.points.push_back({point->id, point->position});
    for (const auto& [observer, index] : point->observations()) {
      const auto it = keyframe_index.find(observer);
      if (it == keyframe_index.end()) continue;
      problem.observations.push_back({it->second, p, observer->observation(index)});
      window.observation_owners.emplace_back(observer, point.get());
    }
  }
}

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

std::size_t LocalMapper::queuedKeyFrames() const {
  std::lock_guard lock(queue_mutex_);
  return queue_.size();
}

void LocalMapper::start() {
  stopping_ = false;
  thread_ = std::thread([this] { run(); });
}

void LocalMapper::finish() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(queue_mutex_);
    stopping_ = true;
  }
  queue_changed_.notify_all();
  thread_.join();
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
  while (auto keyframe = popKeyFrame()) processKeyFrame(keyframe);
}

void LocalMapper::run() {
  while (true) {
    std::shared_ptr<map::KeyFrame> keyframe;
    {
      std::unique_lock lock(queue_mutex_);
      queue_changed_.wait(lock, [this] { return !paused_ && (stopping_ || !queue_.empty()); });
      if (queue_.empty()) return;
      keyframe = queue_.front();
      queue_.pop_front();
      busy_ = true;
    }
    processKeyFrame(keyframe);
    {
      std::lock_guard lock(queue_mutex_);
      busy_ = false;
    }
    queue_changed_.notify_all();
  }
}

std::shared_ptr<map::KeyFrame> LocalMapper::popKeyFrame() {
  std::lock_guard lock(queue_mutex_);
  if (queue_.empty()) return nullptr;
  auto keyframe = queue_.front();
  queue_.pop_front();
  return keyframe;
}

void LocalMapper::processKeyFrame(const std::shared_ptr<map::KeyFrame>& keyframe) {
  {
    std::lock_guard lock(map_.mutex);
    integrateKeyFrame(*keyframe);
    cullRecentPoints(*keyframe);
    fuseWithNeighbours(*keyframe);
  }
  if (queuedKeyFrames() == 0 && map_.numKeyFrames() > 2) localBundleAdjustment(*keyframe);
  {
    std::lock_guard lock(map_.mutex);
    if (options_.cull_keyframes) cullRedundantKeyFrames(*keyframe);
    map_.pruneBadMapPoints();
    if (keyframe->bad) return;
  }
  if (observer_) observer_(keyframe);
}

void LocalMapper::integrateKeyFrame(map::KeyFrame& keyframe) {
  for (const auto& [index, point] : keyframe.validMapPoints()) {
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
    return age >= 3;
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
    buildProblem(window);
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
    if (candidate->id == 0 || candidate->bad) continue;
    int close_points = 0;
    int redundant = 0;
    const double close_depth = candidate->camera->close_depth_m;
    for (const auto& [index, point] : candidate->validMapPoints()) {
      if (candidate->depth[index] <= 0.0f || candidate->depth[index] > close_depth) continue;
      ++close_points;
      if (point->numObservations() <= 3) continue;
      const int level = candidate->keypoints_un[index].octave;
      int seen_at_finer_scale = 0;
      for (const auto& [observer, other_index] : point->observations()) {
        if (observer == candidate) continue;
        if (observer->keypoints_un[other_index].octave <= level + 1) ++seen_at_finer_scale;
        if (seen_at_finer_scale >= 3) break;
      }
      if (seen_at_finer_scale >= 3) ++redundant;
    }
    if (close_points > 0 && redundant > options_.redundant_keyframe_share * close_points) {
      candidate->setBad();
    }
  }
}

}  // namespace segslam::mapping
