#pragma once

#include <cstdint>
#include <set>
#include <vector>

namespace segslam::loop {

// A loop candidate with its neighbourhood: the candidate keyframe and its covisible keyframes.
struct CandidateGroup {
  std::uint64_t candidate = 0;
  std::set<std::uint64_t> keyframes;
};

// Temporal consistency: a candidate is confirmed only when `required_consecutive` consecutive
// query keyframes each proposed a candidate whose group shares a keyframe with a group proposed
// by the query before (the chain of groups walks along one place of the old map). A single
// look-alike keyframe thus never reaches verification on its own.
class ConsistencyCheck {
 public:
  explicit ConsistencyCheck(int required_consecutive = 3);

  // Feeds the candidates of the next query keyframe (none: the chains break) and returns the
  // candidates confirmed by it.
  std::vector<std::uint64_t> update(const std::vector<CandidateGroup>& groups);
  void reset() { chains_.clear(); }

 private:
  struct Chain {
    std::set<std::uint64_t> keyframes;
    int length = 1;  // consecutive queries that supported this place
  };

  int required_consecutive_;
  std::vector<Chain> chains_;
};

}  // namespace segslam::loop
