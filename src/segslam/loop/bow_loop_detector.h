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
  std::size_t shortlist = 50;  // database hits (unmasked score) rescored with the union mask
  double min_score = 0.05;     // union-mask score below which nothing is a candidate
  CandidateGroupOptions groups;
};

// Loop candidates by bag of words with the union mask (the "BoW + union mask"): every
// keyframe's static ORB descriptors become words of the vocabulary in a BowDatabase. A query is
// compared with the database through the inverted index, then the best hits are rescored over
// the keypoints static in BOTH keyframes: the query's keypoints on the hit's dynamic mask and the
// hit's keypoints on the query's mask are left out, so that neither keyframe's moving objects
// take part. A hit must score higher than the lowest such score between the query and its
// covisible keyframes (which truly see the same place: the score's scale differs from scene to
// scene), and at least `min_score`; hits are then pooled by bestCandidateGroups. Keyframes are read
// through pointers: they must outlive the detector (the map keeps even culled keyframes).
class BowLoopDetector : public LoopCandidateDetector {
 public:
  explicit BowLoopDetector(std::shared_ptr<const place::Vocabulary> vocabulary,
                           BowLoopOptions options = {});

  [[nodiscard]] std::string name() const override { return "bow"; }
  void add(const map::KeyFrame& keyframe) override;
  [[nodiscard]] std::vector<std::uint64_t> candidates(const map::KeyFrame& query,
                                                      const std::set<std::uint64_t>& covisible,
                                                      std::size_t max_candidates) const override;

  // A keyframe's static keypoints with their words.
  struct Entry {
    const map::KeyFrame* keyframe = nullptr;
    std::vector<place::WordId> words;
    std::vector<cv::Point2f> pixels;  // raw keypoint positions, for the other's mask
    cv::Mat dynamic_mask;             // empty when nothing in the keyframe moves
    place::BowVector bow;             // all static keypoints
  };

  [[nodiscard]] Entry entryOf(const map::KeyFrame& keyframe) const;
  // Indices of a's keypoints outside b's dynamic mask.
  [[nodiscard]] static std::vector<std::size_t> keypointsStaticIn(const Entry& a, const Entry& b);
  // l1Score of the two keyframes' words over the keypoints static in both.
  [[nodiscard]] double unionMaskScore(const Entry& a, const Entry& b) const;

 private:
  [[nodiscard]] place::BowVector wordsOf(const Entry& entry,
                                         const std::vector<std::size_t>& kept) const;
  [[nodiscard]] const Entry* find(std::uint64_t keyframe_id) const;

  std::shared_ptr<const place::Vocabulary> vocabulary_;
  BowLoopOptions options_;
  place::BowDatabase database_;
  std::vector<Entry> entries_;  // by database entry id
  std::map<std::uint64_t, place::BowDatabase::EntryId> entry_of_keyframe_;
};

}  // namespace segslam::loop
