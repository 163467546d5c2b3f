#pragma once

#include <vector>

#include "segslam/feature/scale_levels.h"

namespace segslam::feature {

// Splits `total` features over the pyramid levels in proportion to each level's area: a geometric
// series with ratio 1/factor^2, so a level gets as many features per pixel as any other. The shares
// are whole numbers that sum exactly to `total`.
std::vector<int> levelFeatureShares(int total, const ScaleLevels& scale_levels);

// Per-level budgets that still reach min(total, sum of capacities) when some level has fewer
// candidates (`capacities`) than its share: what such a level cannot use goes to the levels with
// candidates to spare, in proportion to their shares. This keeps the frame's feature count when a
// dynamic mask or a blank wall empties part of a level.
std::vector<int> allocateLevelBudgets(const std::vector<int>& shares,
                                      const std::vector<int>& capacities);

}  // namespace segslam::feature
