#include "segslam/eval/statistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace segslam::eval {

double median(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("median of an empty list");
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t middle = sorted.size() / 2;
  if (sorted.size() % 2 == 1) return sorted[middle];
  return (sorted[middle - 1] + sorted[middle]) / 2.0;
}

ErrorStatistics computeStatistics(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("statistics of an empty list");
  const auto n = static_cast<double>(values.size());
  double sum = 0.0;
  double sum_of_squares = 0.0;
  for (const double v : values) {
    sum += v;
    sum_of_squares += v * v;
  }
  ErrorStatistics stats;
  stats.count = values.size();
  stats.rmse = std::sqrt(sum_of_squares / n);
  stats.mean = sum / n;
  stats.median = median(values);
  // Squared deviations from the mean rather than E[x^2] - mean^2, which cancels badly.
  double squared_deviations = 0.0;
  for (const double v : values) squared_deviations += (v - stats.mean) * (v - stats.mean);
  stats.std = std::sqrt(squared_deviations / n);
  const auto [min, max] = std::minmax_element(values.begin(), values.end());
  stats.min = *min;
  stats.max = *max;
  return stats;
}

double share(std::size_t part, std::size_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace segslam::eval
