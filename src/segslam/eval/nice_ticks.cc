#include "segslam/eval/nice_ticks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace segslam::eval {

namespace {

// Relative slack so that a value like 0.30000000000000004 still counts as the tick 0.3.
constexpr double kTickTolerance = 1e-9;

}  // namespace

double niceStep(double span, int target_count) {
  const double raw = span / std::max(target_count, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double residual = raw / magnitude;
  if (residual <= 1.0) return magnitude;
  if (residual <= 2.0) return 2.0 * magnitude;
  if (residual <= 5.0) return 5.0 * magnitude;
  return 10.0 * magnitude;
}

AxisRange niceAxis(double low, double high, int target_count) {
  if (!(high > low)) {
    const double pad = low != 0.0 ? std::abs(low) * 0.1 : 1.0;
    low -= pad;
    high += pad;
  }
  const double step = niceStep(high - low, target_count);
  return {std::floor(low / step + kTickTolerance) * step,
          std::ceil(high / step - kTickTolerance) * step, step};
}

std::vector<double> tickValues(double low, double high, double step) {
  std::vector<double> ticks;
  const auto first = static_cast<long long>(std::ceil(low / step - kTickTolerance));
  const auto last = static_cast<long long>(std::floor(high / step + kTickTolerance));
  for (long long k = first; k <= last; ++k) {
    // Adding 0.0 turns -0.0 into 0.0, so no tick reads "-0".
    ticks.push_back(static_cast<double>(k) * step + 0.0);
  }
  return ticks;
}

std::string formatTick(double value, double step) {
  const int decimals =
      std::max(0, -static_cast<int>(std::floor(std::log10(step) + kTickTolerance)));
  return fmt::format("{:.{}f}", value + 0.0, decimals);
}

}  // namespace segslam::eval
