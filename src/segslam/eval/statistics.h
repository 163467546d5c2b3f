#pragma once

#include <cstddef>
#include <span>

namespace segslam::eval {

// Summary of a list of errors, computed as the TUM RGB-D benchmark tools print them (numpy):
// the median of an even count averages the two middle values, std is the population one.
struct ErrorStatistics {
  std::size_t count = 0;
  double rmse = 0.0;
  double mean = 0.0;
  double median = 0.0;
  double std = 0.0;
  double min = 0.0;
  double max = 0.0;
};

// Throws std::invalid_argument for an empty list (callers check their pair counts first).
ErrorStatistics computeStatistics(std::span<const double> values);

double median(std::span<const double> values);

// part / whole, 0 for an empty whole (a share of nothing is reported as none, not NaN).
double share(std::size_t part, std::size_t whole);

}  // namespace segslam::eval
