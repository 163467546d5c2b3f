#include "segslam/eval/closest_index.h"

#include <cmath>
#include <stdexcept>

namespace segslam::eval {

std::size_t findClosestIndex(std::span<const double> sorted, double value) {
  if (sorted.empty()) throw std::invalid_argument("findClosestIndex on an empty list");
  std::size_t begin = 0;
  std::size_t end = sorted.size();
  std::size_t best = 0;
  double best_difference = std::abs(sorted[0] - value);
  while (begin < end) {
    const std::size_t middle = (begin + end) / 2;
    const double difference = std::abs(sorted[middle] - value);
    if (difference < best_difference) {
      best_difference = difference;
      best = middle;
    }
    if (sorted[middle] == value) return middle;
    if (sorted[middle] > value) {
      end = middle;
    } else {
      begin = middle + 1;
    }
  }
  return best;
}

}  // namespace segslam::eval
