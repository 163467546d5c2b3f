#include "segslam/feature/level_budget.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <stdexcept>

namespace segslam::feature {
namespace {

// Splits `total` in proportion to `weights` (zero weight gets nothing) by rounding the cumulative
// sums, so the parts add up to `total` exactly.
std::vector<int> splitProportionally(int total, const std::vector<double>& weights) {
  const double weight_sum = std::accumulate(weights.begin(), weights.end(), 0.0);
  std::vector<int> parts(weights.size(), 0);
  if (weight_sum <= 0.0) return parts;
  double cumulative = 0.0;
  long previous = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    cumulative += weights[i];
    const long upto = std::lround(total * (cumulative / weight_sum));
    parts[i] = static_cast<int>(upto - previous);
    previous = upto;
  }
  return parts;
}

}  // namespace

std::vector<int> levelFeatureShares(int total, const ScaleLevels& scale_levels) {
  std::vector<double> areas;
  for (const double inverse_sigma2 : scale_levels.inverseSigma2()) areas.push_back(inverse_sigma2);
  return splitProportionally(std::max(total, 0), areas);
}

std::vector<int> allocateLevelBudgets(const std::vector<int>& shares,
                                      const std::vector<int>& capacities) {
  if (shares.size() != capacities.size()) {
    throw std::invalid_argument("allocateLevelBudgets: one capacity per level share expected");
  }
  std::vector<int> budgets(shares.size());
  int unplaced = 0;
  for (std::size_t level = 0; level < shares.size(); ++level) {
    budgets[level] = std::min(shares[level], capacities[level]);
    unplaced += shares[level] - budgets[level];
  }
  while (unplaced > 0) {
    std::vector<double> weights(shares.size(), 0.0);
    for (std::size_t level = 0; level < shares.size(); ++level) {
      // A share of at least 1 lets a level whose rounded share was 0 still take spare features.
      if (budgets[level] < capacities[level]) weights[level] = std::max(shares[level], 1);
    }
    const std::vector<int> offers = splitProportionally(unplaced, weights);
    int placed = 0;
    for (std::size_t level = 0; level < shares.size(); ++level) {
      const int taken = std::min(offers[level], capacities[level] - budgets[level]);
      budgets[level] += taken;
      placed += taken;
    }
    if (placed == 0) break;  // no level has room left
    unplaced -= placed;
  }
  return budgets;
}

}  // namespace segslam::feature
