#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include "segslam/map/keyframe.h"

// What the similarity-based loop detectors (bag of words, CNN) share once each has scored the
// query against its keyframes: how high a score must be, and how scores of keyframes that see
// the same place are pooled.
namespace segslam::loop {

enum class CovisibleScore {
  kWeakest,  // the lowest: permissive, for scores with a wide range (bag of words)
  kMean,     // for scores squeezed near their maximum (CNN cosines), where the weakest is too low
};

// A score between the query and its covisible keyframes (which truly see the same place: the
// scale of a score differs from scene to scene), at least `min_score`. `score_of` gives nothing
// for keyframes the detector does not know.
double covisibleScoreThreshold(const map::KeyFrame& query, const std::set<std::uint64_t>& covisible,
                               const std::function<std::optional<double>(std::uint64_t)>& score_of,
                               double min_score, CovisibleScore rule = CovisibleScore::kWeakest);

struct CandidateGroupOptions {
  std::size_t group_neighbours = 10;       // a candidate's best covisibles whose scores it adds
  double min_relative_group_score = 0.75;  // of the best group's accumulated score
};

// Each scored keyframe gathers the scores of its best covisible keyframes that are scored too: a
// revisited place is seen by several keyframes, a look-alike usually by one. Groups within
// `min_relative_group_score` of the best are returned, best first, each by its best-scoring
// keyframe, at most `max_candidates`. `keyframe_of` maps a scored id to its keyframe.
std::vector<std::uint64_t> bestCandidateGroups(
    const std::unordered_map<std::uint64_t, double>& scores,
    const std::function<const map::KeyFrame*(std::uint64_t)>& keyframe_of,
    const CandidateGroupOptions& options, std::size_t max_candidates);

}  // namespace segslam::loop
