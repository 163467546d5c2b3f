#include "segslam/loop/bow_loop_detector.h"

#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "segslam/feature/static_mask.h"

namespace segslam::loop {

BowLoopDetector::BowLoopDetector(std::shared_ptr<const place::Vocabulary> vocabulary,
                                 BowLoopOptions options)
    : vocabulary_(std::move(vocabulary)), options_(options) {
  if (!vocabulary_) throw std::invalid_argument("BowLoopDetector: no vocabulary");
}

BowLoopDetector::Entry BowLoopDetector::entryOf(const map::KeyFrame& keyframe) const {
  Entry entry;
  entry.keyframe = &keyframe;
  // A mask without a dynamic pixel changes no score and would cost a full image per keyframe.
  if (!keyframe.dynamic_mask.empty() && cv::countNonZero(keyframe.dynamic_mask) > 0) {
    entry.dynamic_mask = keyframe.dynamic_mask;
  }
  for (std::size_t i = 0; i < keyframe.keypoints.size(); ++i) {
    const cv::Point2f& pixel = keyframe.keypoints[i].pt;
    if (feature::isDynamicAt(entry.dynamic_mask, pixel)) continue;
    entry.words.push_back(
        vocabulary_->wordOf(keyframe.descriptors.ptr<std::uint8_t>(static_cast<int>(i))));
    entry.pixels.push_back(pixel);
  }
  std::vector<std::size_t> all(entry.words.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  entry.bow = wordsOf(entry, all);
  return entry;
}

place::BowVector BowLoopDetector::wordsOf(const Entry& entry,
                                          const std::vector<std::size_t>& kept) const {
  // Term frequency times IDF, as Vocabulary::transform weighs them.
  place::BowVector bow;
  for (const std::size_t k : kept) {
    const float idf = vocabulary_->idf(entry.words[k]);
    if (idf > 0.0F) bow[entry.words[k]] += idf;
  }
  place::normaliseL1(bow);
  return bow;
}

std::vector<std::size_t> BowLoopDetector::keypointsStaticIn(const Entry& a, const Entry& b) {
  std::vector<std::size_t> kept;
  kept.reserve(a.pixels.size());
  for (std::size_t k = 0; k < a.pixels.size(); ++k) {
    if (!feature::isDynamicAt(b.dynamic_mask, a.pixels[k])) kept.push_back(k);
  }
  return kept;
}

double BowLoopDetector::unionMaskScore(const Entry& a, const Entry& b) const {
  if (a.dynamic_mask.empty() && b.dynamic_mask.empty()) return place::l1Score(a.bow, b.bow);
  return place::l1Score(wordsOf(a, keypointsStaticIn(a, b)), wordsOf(b, keypointsStaticIn(b, a)));
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

std::vector<std::uint64_t> BowLoopDetector::candidates(const map::KeyFrame& query,
                                                       const std::set<std::uint64_t>& covisible,
                                                       std::size_t max_candidates) const {
  const Entry query_entry = entryOf(query);
  const double threshold = covisibleScoreThreshold(
      query, covisible,
      [&](std::uint64_t id) -> std::optional<double> {
        const Entry* neighbour = find(id);
        if (!neighbour) return std::nullopt;
        return unionMaskScore(query_entry, *neighbour);
      },
      options_.min_score);

  const auto hits = database_.query(query_entry.bow, options_.shortlist, [&](auto entry) {
    const map::KeyFrame* keyframe = entries_[entry].keyframe;
    return keyframe->bad || keyframe->id == query.id || covisible.contains(keyframe->id);
  });
  std::unordered_map<std::uint64_t, double> scores;
  for (const auto& hit : hits) {
    const Entry& entry = entries_[hit.entry];
    const double score = unionMaskScore(query_entry, entry);
    if (score > threshold) scores[entry.keyframe->id] = score;
  }
  return bestCandidateGroups(
      scores, [&](std::uint64_t id) { return find(id)->keyframe; }, options_.groups,
      max_candidates);
}

}  // namespace segslam::loop
