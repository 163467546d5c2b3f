#pragma once

#include <utility>
#include <vector>

namespace segslam::io {

// Index pairs (i into `first`, j into `second`) matched by timestamp exactly as the TUM RGB-D
// tools' associate.py does: every pair with |first[i] - (second[j] + offset)| < max_difference is a
// candidate; candidates are taken greedily by increasing difference (ties by first, then second
// timestamp), each timestamp used at most once; the result is sorted by first timestamp.
// Both inputs must be sorted ascending.
std::vector<std::pair<std::size_t, std::size_t>> associateTimestamps(
    const std::vector<double>& first, const std::vector<double>& second, double max_difference,
    double offset = 0.0);

}  // namespace segslam::io
