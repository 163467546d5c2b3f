#include "segslam/loop/bow_loop_detector.h"

#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace segslam::loop {

BowLoopDetector::BowLoopDetector(std::shared_ptr<const place::Vocabulary> vocabulary,
                                 BowLoopOptions options)
    : vocabulary_(std::move(vocabulary)), options_(options) {
  if (!vocabulary_) throw std::invalid_argument("BowLoopDetector: no vocabulary");
}

BowLoopDetector::Entry BowLoopDetector::entryOf(const map::KeyFrame& keyframe) const {
  Entry entry;
  entry.keyframe = &keyframe;
  // Term frequency times IDF, as Vocabulary::transform weighs them.
  for (std::size_t i = 0; i < keyframe.keypoints.size(); ++i) {
    if (keyframe.dynamic_mask.at(keyframe.keypoints[i].pt)) continue;
    const place::WordId word =
        vocabulary_->wordOf(keyframe.descriptors.ptr<std::uint8_t>(static_cast<int>(i)));
    const float idf = vocabulary_->idf(word);
    if (idf > 0.0F) entry.bow[word] += idf;
  }
  place::normaliseL1(entry.bow);
  return entry;
}

const BowLoopDetector::Entry* BowLoopDetector::find(std::uint64_t keyframe_id) const {
  const auto it = entry_of_keyframe_.find(keyframe_id);
  return it == entry_of_keyframe_.end() ? nullptr : &entries_[it->second];
}

void BowLoopDetector::add(const map::KeyFrame& keyframe) {
  Entry entry = entryOf(keyframe);
  const auto id = database_.add(entry.bow);
  entry_of_keyframe_[keyframe.id] = id;
  entries_.push_back(std::move(entry));
}

void BowLoopDetector::forget(std::uint64_t keyframe_id) {
  const auto it = entry_of_keyframe_.find(keyframe_id);
  if (it == entry_of_keyframe_.end()) return;
  database_.remove(it->second);
  place::BowVector().swap(entries_[it->second].bow);
  entry_of_keyframe_.erase(it);
}

std::vector<std::uint64_t> BowLoopDetector::candidates(const map::KeyFrame& query,
                                                       const std::set<std::uint64_t>& covisible,
                                                       std::size_t max_candidates) const {
  const Entry query_entry = entryOf(query);
  const double threshold = covisibleScoreThreshold(
      query, covisible,
      [&](std::uint64_t id) -> std::optional<double> {
        const Entry* neighbour = find(id);
        if (!neighbour) return std::nullopt;
        return place::l1Score(query_entry.bow, neighbour->bow);
      },
      options_.min_score);

  const auto hits = database_.query(query_entry.bow, options_.shortlist, [&](auto entry) {
    const map::KeyFrame* keyframe = entries_[entry].keyframe;
    return keyframe->bad || keyframe->id == query.id || covisible.contains(keyframe->id);
  });
  std::unordered_map<std::uint64_t, double> scores;
  for (const auto& hit : hits) {
    if (hit.score > threshold) scores[entries_[hit.entry].keyframe->id] = hit.score;
  }
  return bestCandidateGroups(
      scores, [&](std::uint64_t id) { return find(id)->keyframe; }, options_.groups,
      max_candidates);
}

}  // namespace segslam::loop
