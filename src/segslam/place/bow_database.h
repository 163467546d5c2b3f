#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "segslam/place/bow_vector.h"

namespace segslam::place {

// Images' bags of words with an inverted index (word -> entries that contain it, with their
// weights) for fast queries, and optionally each entry's direct index (FeatureVector).
class BowDatabase {
 public:
  using EntryId = std::uint32_t;

  struct Result {
    EntryId entry = 0;
    double score = 0.0;  // l1Score with the query, in [0, 1]
  };

  // Adds an image; the vector is L1-normalised on the way in. Returns the entry's id (0, 1, ...).
  EntryId add(const BowVector& vector, FeatureVector feature_vector = {});
  // Forgets an entry: queries never return it again and its vectors are freed. Ids are not
  // reused.
  void remove(EntryId entry);

  // The entries sharing words with the query, best first (ties: lower entry first), at most
  // max_results; entries for which `exclude` returns true are skipped. Scored through the inverted
  // index only: for L1-normalised non-negative vectors, l1Score(a, b) = sum over shared words of
  // min(a_w, b_w), so entries without a shared word (score 0) are never visited.
  [[nodiscard]] std::vector<Result> query(
      const BowVector& vector, std::size_t max_results,
      const std::function<bool(EntryId)>& exclude = nullptr) const;

  // Entries ever added, removed ones included.
  [[nodiscard]] std::size_t size() const { return vectors_.size(); }
  [[nodiscard]] const BowVector& bowVector(EntryId entry) const { return vectors_.at(entry); }
  [[nodiscard]] const FeatureVector& featureVector(EntryId entry) const {
    return feature_vectors_.at(entry);
  }

 private:
  struct Posting {
    EntryId entry;
    double weight;
  };

  std::unordered_map<WordId, std::vector<Posting>> inverted_index_;
  std::vector<BowVector> vectors_;
  std::vector<FeatureVector> feature_vectors_;
};

}  // namespace segslam::place
