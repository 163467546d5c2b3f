#include "segslam/loop/candidate_groups.h"

#include <algorithm>
#include <limits>

namespace segslam::loop {

namespace {

struct ScoredGroup {
  double score = 0.0;
  std::uint64_t best_keyframe = 0;
};

ScoredGroup groupAround(std::uint64_t id, double score,
                        const std::unordered_map<std::uint64_t, double>& scores,
                        const map::KeyFrame& keyframe, std::size_t group_neighbours) {
  ScoredGroup group{score, id};
  double best = score;
  for (const map::KeyFrame* neighbour : keyframe.bestCovisibles(group_neighbours)) {
    const auto it = scores.find(neighbour->id);
    if (it == scores.end()) continue;
    group.score += it->second;
    if (it->second > best) {
      best = it->second;
      group.best_keyframe = neighbour->id;
    }
  }
  return group;
}

}  // namespace

double covisibleScoreThreshold(const map::KeyFrame& query, const std::set<std::uint64_t>& covisible,
                               const std::function<std::optional<double>(std::uint64_t)>& score_of,
                               double min_score, CovisibleScore rule) {
  double weakest = std::numeric_limits<double>::infinity();
  double sum = 0.0;
  int count = 0;
  for (const std::uint64_t id : covisible) {
    if (id == query.id) continue;
    if (const auto score = score_of(id)) {
      weakest = std::min(weakest, *score);
      sum += *score;
      ++count;
    }
  }
  if (count == 0) return min_score;
  return std::max(rule == CovisibleScore::kWeakest ? weakest : sum / count, min_score);
}

std::vector<std::uint64_t> bestCandidateGroups(
    const std::unordered_map<std::uint64_t, double>& scores,
    const std::function<const map::KeyFrame*(std::uint64_t)>& keyframe_of,
    const CandidateGroupOptions& options, std::size_t max_candidates) {
  std::vector<ScoredGroup> groups;
  for (const auto& [id, score] : scores) {
    groups.push_back(groupAround(id, score, scores, *keyframe_of(id), options.group_neighbours));
  }
  std::sort(groups.begin(), groups.end(), [](const ScoredGroup& a, const ScoredGroup& b) {
    return a.score != b.score ? a.score > b.score : a.best_keyframe < b.best_keyframe;
  });
  std::vector<std::uint64_t> result;
  for (const ScoredGroup& group : groups) {
    if (result.size() >= max_candidates ||
        group.score < options.min_relative_group_score * groups.front().score) {
      break;
    }
    if (std::find(result.begin(), result.end(), group.best_keyframe) == result.end()) {
      result.push_back(group.best_keyframe);
    }
  }
  return result;
}

}  // namespace segslam::loop
