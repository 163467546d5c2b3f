#include "segslam/loop/loop_closer.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

#include "segslam/mapping/point_fusion.h"
#include "segslam/optim/bundle_adjuster.h"
#include "segslam/util/elapsed_time.h"

namespace segslam::loop {

namespace {

using KeyFramePoses = std::map<const map::KeyFrame*, geometry::Pose>;

// How a keyframe's correction moves world points: X_new = T_new^-1 * T_old * X.
geometry::Pose worldCorrection(const geometry::Pose& T_old, const geometry::Pose& T_new) {
  return geometry::orthonormalised(T_new.inverse() * T_old);
}

// Every keypoint of the keyframe with a trusted depth, placed in the world by the keyframe's pose:
// RGB-D sees the place even where the map kept no point (points seen by fewer than three
// keyframes are culled, and a fast turn leaves few). The keypoint's map point comes along when
// there is one, for fusion.
void appendKeyPoints(const map::KeyFrame& keyframe, std::vector<LoopMapPoint>& points) {
  for (std::size_t i = 0; i < keyframe.size(); ++i) {
    const float depth = keyframe.depth[i];
    if (depth <= 0.0f || depth > keyframe.camera->close_depth_m) continue;
    const auto& point = keyframe.mapPoints()[i];
    points.push_back({point && !point->bad ? point : nullptr, keyframe.unproject(i),
                      keyframe.descriptors.row(static_cast<int>(i)).clone()});
  }
}

// The keyframe whose correction a map point follows: its reference, or its first live observer.
const map::KeyFrame* anchorOf(const map::MapPoint& point) {
  if (point.reference_keyframe != nullptr && !point.reference_keyframe->bad) {
    return point.reference_keyframe;
  }
  for (const auto& [observer, index] : point.observations()) {
    if (!observer->bad) return observer;
  }
  return nullptr;
}

// Moves every live keyframe and point by the correction of its keyframe, from `before` to the
// keyframe's current pose; keyframes and points created since `before` was taken follow the
// newest keyframe of `before`.
void propagateCorrections(map::Map& map, const KeyFramePoses& before,
                          const std::map<const map::KeyFrame*, geometry::Pose>& after) {
  std::map<const map::KeyFrame*, geometry::Pose> corrections;
  const map::KeyFrame* newest = nullptr;
  for (const auto& [keyframe, T_old] : before) {
    const auto it = after.find(keyframe);
    if (it == after.end()) continue;
    corrections[keyframe] = worldCorrection(T_old, it->second);
    if (newest == nullptr || keyframe->id > newest->id) newest = keyframe;
  }
  if (newest == nullptr) return;
  const geometry::Pose newest_correction = corrections.at(newest);
  auto correctionOf = [&](const map::KeyFrame* keyframe) {
    const auto it = corrections.find(keyframe);
    return it == corrections.end() ? newest_correction : it->second;
  };
  for (const auto& point : map.mapPoints()) {
    const map::KeyFrame* anchor = anchorOf(*point);
    if (anchor == nullptr) continue;
    point->position = correctionOf(anchor) * point->position;
    point->updateNormalAndDepth();
  }
  for (const auto& keyframe : map.keyFrames()) {
    const auto it = after.find(keyframe.get());
    keyframe->T_cw = it != after.end()
                         ? it->second
                         : geometry::orthonormalised(keyframe->T_cw * newest_correction.inverse());
  }
  map.notifyCorrection();
}

}  // namespace

LoopCloser::LoopCloser(map::Map& map, mapping::LocalMapper& mapper,
                       std::unique_ptr<LoopCandidateDetector> detector, LoopClosingOptions options)
    : map_(map),
      mapper_(mapper),
      detector_(std::move(detector)),
      options_(options),
      consistency_(options.consecutive_queries) {
  stats_.detector = detector_->name();
}

LoopCloser::~LoopCloser() { finish(); }

void LoopCloser::insertKeyFrame(std::shared_ptr<map::KeyFrame> keyframe) {
  {
    std::lock_guard lock(queue_mutex_);
    queue_.push_back(std::move(keyframe));
  }
  queue_changed_.notify_all();
}

void LoopCloser::start() {
  stopping_ = false;
  thread_ = std::thread([this] { run(); });
}

void LoopCloser::finish() {
  if (thread_.joinable()) {
    {
      std::lock_guard lock(queue_mutex_);
      stopping_ = true;
    }
    queue_changed_.notify_all();
    thread_.join();
  }
  processQueued();
  if (global_ba_thread_.joinable()) global_ba_thread_.join();
}

void LoopCloser::processQueued() {
  while (auto keyframe = popKeyFrame()) processKeyFrame(keyframe);
}

LoopClosingStats LoopCloser::stats() const {
  std::lock_guard lock(stats_mutex_);
  return stats_;
}

void LoopCloser::run() {
  while (true) {
    std::shared_ptr<map::KeyFrame> keyframe;
    {
      std::unique_lock lock(queue_mutex_);
      queue_changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;
      keyframe = queue_.front();
      queue_.pop_front();
    }
    processKeyFrame(keyframe);
  }
}

void LoopCloser::addRestoredKeyFrame(map::KeyFrame& keyframe, const std::string& description) {
  keyframes_by_id_[keyframe.id] = &keyframe;
  detector_->addRestored(keyframe, description);
}

std::string LoopCloser::savedDescription(std::uint64_t keyframe_id) const {
  return detector_->savedDescription(keyframe_id);
}

std::shared_ptr<map::KeyFrame> LoopCloser::popKeyFrame() {
  std::lock_guard lock(queue_mutex_);
  if (queue_.empty()) return nullptr;
  auto keyframe = queue_.front();
  queue_.pop_front();
  return keyframe;
}

void LoopCloser::processKeyFrame(const std::shared_ptr<map::KeyFrame>& keyframe) {
  const auto describe_start = std::chrono::steady_clock::now();
  detector_->describe(*keyframe);
  {
    std::lock_guard lock(stats_mutex_);
    ++stats_.keyframes_described;
    stats_.describe_ms_total += util::millisecondsSince(describe_start);
  }
  std::vector<std::uint64_t> confirmed;
  {
    std::lock_guard lock(map_.mutex);
    // The image was kept for describe() only: a keyframe's pixels would dominate the map's memory.
    keyframe->image.release();
    forgetCulledKeyFrames(keyframe->id);
    if (keyframe->bad) return;
    keyframes_by_id_[keyframe->id] = keyframe.get();
    confirmed = confirmedCandidates(*keyframe);
    detector_->add(*keyframe);
  }
  for (std::uint64_t candidate : confirmed) {
    if (tryLoop(keyframe, candidate)) break;
  }
}

void LoopCloser::forgetCulledKeyFrames(std::uint64_t described) {
  for (auto it = keyframes_by_id_.begin(); it != keyframes_by_id_.end();) {
    if (it->second->bad) {
      detector_->forget(it->first);
      it = keyframes_by_id_.erase(it);
    } else {
      ++it;
    }
  }
  // Keyframes are described in the order they were made: none up to `described` is read again
  // outside the map mutex.
  map_.releaseCulledKeyFrames(described);
}

std::vector<std::uint64_t> LoopCloser::confirmedCandidates(map::KeyFrame& keyframe) {
  // Keyframe ids count every keyframe made, culled ones included: how far the camera has come.
  const bool too_early =
      keyframe.id < options_.min_keyframes ||
      (any_loop_ && keyframe.id < last_loop_keyframe_ + options_.keyframes_after_loop);
  if (too_early) {
    consistency_.reset();
    return {};
  }
  std::set<std::uint64_t> covisible = {keyframe.id};
  for (const map::KeyFrame* k : keyframe.covisiblesWithWeight(0)) covisible.insert(k->id);
  std::vector<CandidateGroup> groups;
  for (std::uint64_t id : detector_->candidates(keyframe, covisible, options_.max_candidates)) {
    const auto it = keyframes_by_id_.find(id);
    if (it == keyframes_by_id_.end() || it->second->bad) continue;
    if (id + options_.min_keyframes_back > keyframe.id) continue;
    CandidateGroup group{id, {id}};
    for (const map::KeyFrame* k : it->second->covisiblesWithWeight(0))
      group.keyframes.insert(k->id);
    spdlog::debug("loop candidate for keyframe {}: keyframe {}", keyframe.id, id);
    groups.push_back(std::move(group));
  }
  return consistency_.update(groups);
}

bool LoopCloser::tryLoop(const std::shared_ptr<map::KeyFrame>& query, std::uint64_t candidate_id) {
  LoopQuery loop_query;
  std::vector<LoopMapPoint> candidate_points;
  std::vector<LoopMapPoint> local_map;
  std::vector<std::shared_ptr<map::MapPoint>> local_points;
  map::KeyFrame* candidate = nullptr;
  {
    std::lock_guard lock(map_.mutex);
    candidate = keyframes_by_id_.at(candidate_id);
    if (query->bad || candidate->bad) return false;
    loop_query = LoopQuery::of(*query);
    appendKeyPoints(*candidate, candidate_points);
    std::set<std::uint64_t> seen;
    // The query's own neighbourhood would only confirm the drifted pose.
    const auto query_covisibles = query->covisiblesWithWeight(0);
    const std::set<const map::KeyFrame*> query_side(query_covisibles.begin(),
                                                    query_covisibles.end());
    std::vector<map::KeyFrame*> neighbourhood = {candidate};
    for (map::KeyFrame* k : candidate->bestCovisibles(options_.loop_local_keyframes)) {
      if (!k->bad && k != query.get() && !query_side.contains(k)) neighbourhood.push_back(k);
    }
    for (map::KeyFrame* k : neighbourhood) {
      appendKeyPoints(*k, local_map);
      for (const auto& [index, point] : k->validMapPoints()) {
        if (!point->isObservedBy(query.get()) && seen.insert(point->id).second) {
          local_points.push_back(point);
        }
      }
    }
  }
  const LoopVerification verification =
      verifyLoop(loop_query, candidate_points, local_map, options_.verifier);
  {
    std::lock_guard lock(stats_mutex_);
    ++stats_.consistent_candidates;
  }
  spdlog::debug(
      "loop candidate {} for keyframe {}: {} candidate points, {} local points, {} matches, "
      "{} RANSAC inliers, {} inliers",
      candidate_id, query->id, candidate_points.size(), local_map.size(), verification.matches,
      verification.ransac_inliers, verification.inliers);
  if (!verification.accepted) return false;
  correctLoop(*query, *candidate, verification, local_points);
  return true;
}

void LoopCloser::correctLoop(map::KeyFrame& query, map::KeyFrame& loop_keyframe,
                             const LoopVerification& verification,
                             const std::vector<std::shared_ptr<map::MapPoint>>& loop_points) {
  mapper_.pause();
  stopGlobalBundleAdjustment();
  KeyFramePoses before;
  std::vector<std::pair<map::KeyFrame*, map::KeyFrame*>> new_loop_edges;
  {
    std::lock_guard lock(map_.mutex);
    if (query.bad || loop_keyframe.bad) {
      mapper_.resume();
      return;
    }
    for (const auto& keyframe : map_.keyFrames()) before[keyframe.get()] = keyframe->T_cw;
    LoopRecord record{query.id,
                      loop_keyframe.id,
                      query.timestamp,
                      loop_keyframe.timestamp,
                      verification.T_cw * loop_keyframe.T_cw.inverse(),
                      verification.inliers,
                      (query.cameraCentre() - verification.T_cw.inverse().translation()).norm()};

    // The query's neighbourhood moves rigidly with the query onto the loop's map.
    std::vector<map::KeyFrame*> group = {&query};
    for (map::KeyFrame* k : query.covisiblesWithWeight(0)) {
      if (!k->bad) group.push_back(k);
    }
    const std::set<const map::KeyFrame*> group_set(group.begin(), group.end());
    // Points anchored elsewhere follow their anchor in the essential graph.
    const geometry::Pose query_correction = worldCorrection(query.T_cw, verification.T_cw);
    std::set<std::shared_ptr<map::MapPoint>> group_points;
    for (map::KeyFrame* k : group) {
      for (const auto& [index, point] : k->validMapPoints()) {
        const map::KeyFrame* anchor = anchorOf(*point);
        if (!group_points.insert(point).second || !group_set.contains(anchor)) continue;
        point->position = query_correction * point->position;
      }
    }
    for (map::KeyFrame* k : group) {
      k->T_cw = geometry::orthonormalised(k->T_cw * query_correction.inverse());
    }

    std::map<map::KeyFrame*, std::set<map::KeyFrame*>> old_connections;
    for (map::KeyFrame* k : group) {
      const auto covisibles = k->covisiblesWithWeight(0);
      old_connections[k] = {covisibles.begin(), covisibles.end()};
    }
    for (const auto& [index, loop_point] : verification.matched_points) {
      if (!loop_point || loop_point->bad || loop_point->isObservedBy(&query)) continue;
      const auto existing = query.mapPoints()[index];
      if (existing && !existing->bad) {
        existing->replaceWith(loop_point);
      } else {
        loop_point->addObservation(&query, index);
        query.addMapPoint(loop_point, index);
      }
    }
    for (map::KeyFrame* k : group) mapping::fuseIntoKeyFrame(*k, loop_points);
    for (map::KeyFrame* k : group) {
      for (const auto& [index, point] : k->validMapPoints()) {
        point->updateDescriptor();
        point->updateNormalAndDepth();
      }
    }
    for (map::KeyFrame* k : group) k->updateConnections();
    for (map::KeyFrame* k : group) {
      for (map::KeyFrame* other : k->covisiblesWithWeight(0)) {
        if (!group_set.contains(other) && !old_connections[k].contains(other)) {
          new_loop_edges.emplace_back(k, other);
        }
      }
    }
    if (std::none_of(new_loop_edges.begin(), new_loop_edges.end(), [&](const auto& e) {
          return e.first == &query && e.second == &loop_keyframe;
        })) {
      new_loop_edges.emplace_back(&query, &loop_keyframe);
    }
    map_.notifyCorrection();
    spdlog::info(
        "loop closed: keyframe {} (t {:.2f}) sees keyframe {} (t {:.2f}), {} inliers, "
        "drift {:.3f} m, {} loop edges",
        query.id, query.timestamp, loop_keyframe.id, loop_keyframe.timestamp, verification.inliers,
        record.drift_m, new_loop_edges.size());
    std::lock_guard stats_lock(stats_mutex_);
    ++stats_.loops_accepted;
    stats_.loops.push_back(record);
  }
  optimiseEssentialGraph(before, new_loop_edges);
  loop_edges_.insert(loop_edges_.end(), new_loop_edges.begin(), new_loop_edges.end());
  consistency_.reset();
  any_loop_ = true;
  last_loop_keyframe_ = query.id;
  mapper_.resume();
  if (options_.global_bundle_adjustment) startGlobalBundleAdjustment();
}

void LoopCloser::optimiseEssentialGraph(
    const KeyFramePoses& before,
    const std::vector<std::pair<map::KeyFrame*, map::KeyFrame*>>& new_loop_edges) {
  PoseGraph graph;
  std::vector<map::KeyFrame*> nodes;
  KeyFramePoses at_build;
  {
    std::lock_guard lock(map_.mutex);
    std::map<const map::KeyFrame*, std::size_t> index;
    for (const auto& keyframe : map_.keyFrames()) {
      if (!before.contains(keyframe.get())) continue;
      index[keyframe.get()] = nodes.size();
      nodes.push_back(keyframe.get());
      at_build[keyframe.get()] = keyframe->T_cw;
      graph.nodes.push_back({keyframe->id, keyframe->T_cw, keyframe->id == 0});
    }
    // Tracking and local BA made the relative poses before the correction: drift-free locally.
    auto addEdge = [&](map::KeyFrame* a, map::KeyFrame* b, const KeyFramePoses& poses) {
      const auto ia = index.find(a);
      const auto ib = index.find(b);
      if (ia == index.end() || ib == index.end()) return;
      graph.edges.push_back({ia->second, ib->second, poses.at(a) * poses.at(b).inverse(), 1.0});
    };
    std::set<std::pair<std::uint64_t, std::uint64_t>> linked;
    auto link = [&](map::KeyFrame* a, map::KeyFrame* b) {
      return linked.insert({std::min(a->id, b->id), std::max(a->id, b->id)}).second;
    };
    for (const auto& [a, b] : new_loop_edges) {
      if (link(a, b)) addEdge(a, b, at_build);
    }
    for (const auto& [a, b] : loop_edges_) {
      if (link(a, b)) addEdge(a, b, before);
    }
    for (map::KeyFrame* k : nodes) {
      if (k->parent != nullptr && link(k, k->parent)) addEdge(k->parent, k, before);
      for (map::KeyFrame* other : k->covisiblesWithWeight(options_.essential_covisibility_weight)) {
        if (link(k, other)) addEdge(k, other, before);
      }
    }
  }
  const int iterations = optimisePoseGraph(graph, options_.pose_graph);
  spdlog::debug("essential graph: {} keyframes, {} edges, {} iterations", graph.nodes.size(),
                graph.edges.size(), iterations);
  std::lock_guard lock(map_.mutex);
  KeyFramePoses after;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i]->bad) after[nodes[i]] = graph.nodes[i].T_cw;
  }
  propagateCorrections(map_, at_build, after);
}

void LoopCloser::startGlobalBundleAdjustment() {
  cancel_global_ba_ = false;
  if (!thread_.joinable()) {
    globalBundleAdjustment();
    return;
  }
  global_ba_thread_ = std::thread([this] { globalBundleAdjustment(); });
}

void LoopCloser::stopGlobalBundleAdjustment() {
  cancel_global_ba_ = true;
  if (global_ba_thread_.joinable()) global_ba_thread_.join();
}

void LoopCloser::globalBundleAdjustment() {
  optim::BundleAdjustmentProblem problem;
  std::vector<map::KeyFrame*> keyframes;
  std::vector<std::shared_ptr<map::MapPoint>> points;
  KeyFramePoses at_build;
  {
    std::lock_guard lock(map_.mutex);
    std::map<const map::KeyFrame*, std::size_t> index;
    for (const auto& keyframe : map_.keyFrames()) {
      index[keyframe.get()] = keyframes.size();
      keyframes.push_back(keyframe.get());
      at_build[keyframe.get()] = keyframe->T_cw;
      problem.keyframes.push_back({keyframe->id, keyframe->T_cw, keyframe->id == 0});
    }
    if (keyframes.empty()) return;
    problem.intrinsics = keyframes.front()->camera->stereo;
    for (const auto& point : map_.mapPoints()) {
      const std::size_t p = points.size();
      bool observed = false;
      for (const auto& [observer, i] : point->observations()) {
        const auto it = index.find(observer);
        if (it == index.end()) continue;
        problem.observations.push_back({it->second, p, observer->observation(i)});
        observed = true;
      }
      if (!observed) continue;
      points.push_back(point);
      problem.points.push_back({point->id, point->position});
    }
  }
  optim::BundleAdjustmentOptions ba_options;
  ba_options.iterations_first = options_.global_ba_first_iterations;
  ba_options.iterations_second = options_.global_ba_second_iterations;
  ba_options.cancel = &cancel_global_ba_;
  optim::bundleAdjust(problem, ba_options);

  std::lock_guard lock(map_.mutex);
  if (cancel_global_ba_) {
    std::lock_guard stats_lock(stats_mutex_);
    ++stats_.global_bas_cancelled;
    return;
  }
  // Points the BA refined take its positions; the rest (new since) follow their keyframe.
  KeyFramePoses after;
  for (std::size_t k = 0; k < keyframes.size(); ++k) {
    if (!keyframes[k]->bad) after[keyframes[k]] = problem.keyframes[k].T_cw;
  }
  propagateCorrections(map_, at_build, after);
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (points[p]->bad) continue;
    points[p]->position = problem.points[p].position;
    points[p]->updateNormalAndDepth();
  }
  spdlog::info("global BA: {} keyframes, {} points", keyframes.size(), points.size());
  std::lock_guard stats_lock(stats_mutex_);
  ++stats_.global_bas_completed;
}

}  // namespace segslam::loop
