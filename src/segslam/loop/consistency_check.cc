#include "segslam/loop/consistency_check.h"

#include <algorithm>

namespace segslam::loop {

namespace {

bool intersects(const std::set<std::uint64_t>& a, const std::set<std::uint64_t>& b) {
  return std::any_of(a.begin(), a.end(), [&](std::uint64_t id) { return b.contains(id); });
}

}  // namespace

ConsistencyCheck::ConsistencyCheck(int required_consecutive)
    : required_consecutive_(std::max(1, required_consecutive)) {}

std::vector<std::uint64_t> ConsistencyCheck::update(const std::vector<CandidateGroup>& groups) {
  std::vector<Chain> next;
  std::vector<std::uint64_t> confirmed;
  for (const CandidateGroup& group : groups) {
    int length = 1;
    for (const Chain& chain : chains_) {
      if (intersects(chain.keyframes, group.keyframes)) length = std::max(length, chain.length + 1);
    }
    next.push_back({group.keyframes, length});
    if (length >= required_consecutive_) confirmed.push_back(group.candidate);
  }
  chains_ = std::move(next);
  return confirmed;
}

}  // namespace segslam::loop
