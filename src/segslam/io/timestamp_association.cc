#include "segslam/io/timestamp_association.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace segslam::io {

std::vector<std::pair<std::size_t, std::size_t>> associateTimestamps(
    const std::vector<double>& first, const std::vector<double>& second, double max_difference,
    double offset) {
  // Candidates are found with a sliding window over the sorted `second` list rather than the
  // tools' all-pairs loop; the greedy order and tie-breaking are the same.
  std::vector<std::tuple<double, double, double, std::size_t, std::size_t>> candidates;
  std::size_t window_start = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    const double a = first[i];
    while (window_start < second.size() && second[window_start] + offset <= a - max_difference) {
      ++window_start;
    }
    for (std::size_t j = window_start; j < second.size(); ++j) {
      const double diff = std::abs(a - (second[j] + offset));
      if (second[j] + offset >= a + max_difference) break;
      if (diff < max_difference) candidates.emplace_back(diff, a, second[j], i, j);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> first_used(first.size(), false);
  std::vector<bool> second_used(second.size(), false);
  std::vector<std::pair<std::size_t, std::size_t>> matches;
  for (const auto& [diff, a, b, i, j] : candidates) {
    if (first_used[i] || second_used[j]) continue;
    first_used[i] = second_used[j] = true;
    matches.emplace_back(i, j);
  }
  std::sort(matches.begin(), matches.end());
  return matches;
}

}  // namespace segslam::io
