#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "segslam/loop/candidate_groups.h"
#include "segslam/loop/loop_candidate_detector.h"
#include "segslam/place/bow_database.h"
#include "segslam/place/vocabulary.h"

namespace segslam::loop {

struct BowLoopOptions {
  std::size_t shortlist = 50;  // best database hits considered
  double min_score = 0.05;     // score below which nothing is a candidate
  CandidateGroupOptions groups;
};

// Loop candidates by bag of words with the dynamic masks: every keyframe's static ORB descriptors
// (extracted on its static area, so the whole feature budget goes to what is static) become words
// of the vocabulary in a BowDatabase, and a query is scored against the database through the
// inverted index. The other keyframe's mask removes nothing: two views of one place are not
// pixel-aligned, so the keypoints at the pixels of the other's moving object are as often seen by
// the other as any (`segslam eval loops`: bow:static against bow's union of keypoints). A hit must
// score higher than the lowest score between the query and its covisible keyframes (which truly
// see the same place: the score's scale differs from scene to scene), and at least `min_score`;
// hits are then pooled by bestCandidateGroups. Keyframes are read through pointers: they must
// outlive the detector (the map keeps even culled keyframes, as nodes of its pose tree).
class BowLoopDetector : public LoopCandidateDetector {
 public:
  explicit BowLoopDetector(std::shared_ptr<const place::Vocabulary> vocabulary,
                           BowLoopOptions options = {});

  [[nodiscard]] std::string name() const override { return "bow"; }
  void add(const map::KeyFrame& keyframe) override;
  void forget(std::uint64_t keyframe_id) override;
  [[nodiscard]] std::vector<std::uint64_t> candidates(const map::KeyFrame& query,
                                                      const std::set<std::uint64_t>& covisible,
                                                      std::size_t max_candidates) const override;

  // A keyframe and the bag of words of its static keypoints.
  struct Entry {
    const map::KeyFrame* keyframe = nullptr;
    place::BowVector bow;
  };

  // Only the keypoints off the keyframe's own dynamic mask count.
  [[nodiscard]] Entry entryOf(const map::KeyFrame& keyframe) const;

 private:
  [[nodiscard]] const Entry* find(std::uint64_t keyframe_id) const;

  std::shared_ptr<const place::Vocabulary> vocabulary_;
  BowLoopOptions options_;
  place::BowDatabase database_;
  std::vector<Entry> entries_;  // by database entry id
  std::map<std::uint64_t, place::BowDatabase::EntryId> entry_of_keyframe_;
};

}  // namespace segslam::loop
