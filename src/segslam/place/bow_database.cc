#include "segslam/place/bow_database.h"

#include <algorithm>
#include <utility>

namespace segslam::place {

BowDatabase::EntryId BowDatabase::add(const BowVector& vector, FeatureVector feature_vector) {
  const auto entry = static_cast<EntryId>(vectors_.size());
  BowVector normalised = vector;
  normaliseL1(normalised);
  for (const auto& [word, weight] : normalised) {
    if (weight > 0.0) inverted_index_[word].push_back({entry, weight});
  }
  vectors_.push_back(std::move(normalised));
  feature_vectors_.push_back(std::move(feature_vector));
  return entry;
}

void BowDatabase::remove(EntryId entry) {
  BowVector& vector = vectors_.at(entry);
  for (const auto& [word, weight] : vector) {
    const auto postings = inverted_index_.find(word);
    if (postings == inverted_index_.end()) continue;
    std::erase_if(postings->second, [entry](const Posting& p) { return p.entry == entry; });
    if (postings->second.empty()) inverted_index_.erase(postings);
  }
  BowVector().swap(vector);
  FeatureVector().swap(feature_vectors_.at(entry));
}

std::vector<BowDatabase::Result> BowDatabase::query(
    const BowVector& vector, std::size_t max_results,
    const std::function<bool(EntryId)>& exclude) const {
  BowVector normalised = vector;
  normaliseL1(normalised);
  std::unordered_map<EntryId, double> scores;
  for (const auto& [word, weight] : normalised) {
    const auto postings = inverted_index_.find(word);
    if (weight <= 0.0 || postings == inverted_index_.end()) continue;
    for (const Posting& posting : postings->second) {
      if (exclude && exclude(posting.entry)) continue;
      scores[posting.entry] += std::min(weight, posting.weight);
    }
  }
  std::vector<Result> results;
  results.reserve(scores.size());
  for (const auto& [entry, score] : scores) results.push_back({entry, std::min(score, 1.0)});
  const auto better = [](const Result& a, const Result& b) {
    return a.score != b.score ? a.score > b.score : a.entry < b.entry;
  };
  const std::size_t kept = std::min(max_results, results.size());
  std::partial_sort(results.begin(), results.begin() + static_cast<std::ptrdiff_t>(kept),
                    results.end(), better);
  results.resize(kept);
  return results;
}

}  // namespace segslam::place
