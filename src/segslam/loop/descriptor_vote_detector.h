#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segslam/feature/run_length_mask.h"
#include "segslam/loop/loop_candidate_detector.h"

namespace segslam::loop {

struct DescriptorVoteOptions {
  int signature_size = 200;          // strongest keypoints kept per keyframe
  int max_distance = 50;             // Hamming bits for a vote
  double ratio = 0.8;                // best vs second best within the candidate's signature
  double min_score = 0.08;           // share of the query's signature that must find a match
  double min_relative_score = 0.75;  // of the best candidate's score
};

// A loop-candidate detector that needs no vocabulary: each keyframe keeps the descriptors of its
// `signature_size` strongest keypoints on the static area; a query scores every remembered
// keyframe by the share of its signature that finds an unambiguous match in the other's. Only
// keypoints outside the union of both keyframes' dynamic masks vote. Candidates must score at
// least as well as the weakest covisible keyframe (which truly sees the same place), at least
// `min_score`, and within `min_relative_score` of the best.
// Cost: signature_size^2 Hamming distances per remembered keyframe and query (40 000 for 200,
// about 0.1 ms; 10 ms per query on a 100-keyframe map), linear in the map size, and 6.4 kB of
// descriptors per keyframe. A vocabulary (BoW) or CNN descriptor replaces it at scale.
class DescriptorVoteDetector : public LoopCandidateDetector {
 public:
  explicit DescriptorVoteDetector(DescriptorVoteOptions options = {});

  [[nodiscard]] std::string name() const override { return "vote"; }
  void add(const map::KeyFrame& keyframe) override;
  void forget(std::uint64_t keyframe_id) override;
  [[nodiscard]] std::vector<std::uint64_t> candidates(const map::KeyFrame& query,
                                                      const std::set<std::uint64_t>& covisible,
                                                      std::size_t max_candidates) const override;

  struct Signature {
    std::uint64_t keyframe_id = 0;
    cv::Mat descriptors;              // signature_size x 32 CV_8U
    std::vector<cv::Point2f> pixels;  // raw keypoint positions, for the other's mask
    feature::RunLengthMask dynamic_mask;
  };

  [[nodiscard]] Signature signatureOf(const map::KeyFrame& keyframe) const;
  // Share of a's signature (outside b's dynamic mask) matched in b's (outside a's mask).
  [[nodiscard]] double score(const Signature& a, const Signature& b) const;

 private:
  DescriptorVoteOptions options_;
  std::vector<Signature> signatures_;
};

}  // namespace segslam::loop
