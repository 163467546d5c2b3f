#pragma once

#include <string>
#include <vector>

namespace segslam::eval {

// A round step (1, 2 or 5 times a power of ten) that cuts `span` into about `target_count` parts.
double niceStep(double span, int target_count);

// A plot axis range and its tick step.
struct AxisRange {
  double low = 0.0;
  double high = 1.0;
  double step = 0.2;
};

// The range [low, high] widened outwards to multiples of a nice step. An empty or inverted range
// is widened around its value first, so constant data still gets a readable axis.
AxisRange niceAxis(double low, double high, int target_count = 5);

// The multiples of `step` within [low, high] (with a little tolerance for rounding).
std::vector<double> tickValues(double low, double high, double step);

// A tick label with just enough decimals for the step, e.g. 0.05 -> "0.15", 5 -> "15".
std::string formatTick(double value, double step);

}  // namespace segslam::eval
