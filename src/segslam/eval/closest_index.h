#pragma once

#include <cstddef>
#include <span>

namespace segslam::eval {

// Index of the value in `sorted` (ascending, non-empty) closest to `value`, found with exactly
// the binary search of TUM evaluate_rpe.py's find_closest_index. It only looks at the values the
// search visits, so ties and unusual inputs resolve as in the tool, which RPE must reproduce.
std::size_t findClosestIndex(std::span<const double> sorted, double value);

}  // namespace segslam::eval
