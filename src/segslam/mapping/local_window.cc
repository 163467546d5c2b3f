#include "segslam/mapping/local_window.h"

#include <algorithm>
#include <map>
#include <set>

namespace segslam::mapping {

namespace {

void collectKeyFramesAndPoints(LocalWindow& window, map::KeyFrame& keyframe,
                               std::size_t max_keyframes) {
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

void anchor(optim::BundleAdjustmentProblem& problem) {
  const auto fixed_observations = static_cast<std::size_t>(std::count_if(
      problem.observations.begin(), problem.observations.end(),
      [&](const optim::BaObservation& o) { return problem.keyframes[o.keyframe].fixed; }));
  if (fixed_observations >= kMinAnchorObservations || problem.keyframes.size() < 2) return;
  // The first keyframe is the new one, the least settled.
  const auto oldest_optimised =
      std::min_element(problem.keyframes.begin() + 1, problem.keyframes.end(),
                       [](const optim::BaKeyFrame& a, const optim::BaKeyFrame& b) {
                         if (a.fixed != b.fixed) return !a.fixed;
                         return a.id < b.id;
                       });
  oldest_optimised->fixed = true;
}

}  // namespace

LocalWindow collectLocalWindow(map::KeyFrame& keyframe, std::size_t max_keyframes) {
  LocalWindow window;
  collectKeyFramesAndPoints(window, keyframe, max_keyframes);
  buildProblem(window);
  anchor(window.problem);
  return window;
}

}  // namespace segslam::mapping
