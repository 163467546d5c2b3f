#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "segslam/core/trajectory.h"
#include "segslam/eval/rpe_pairs.h"
#include "segslam/eval/statistics.h"

namespace segslam::eval {

// Options of TUM evaluate_rpe.py (same defaults, except that a fixed delta is the default here).
struct RpeOptions {
  // true: pairs `delta` apart (--fixed_delta); false: all pairs, or max_pairs random ones.
  bool fixed_delta = true;
  double delta = 1.0;
  DeltaUnit delta_unit = DeltaUnit::kSeconds;
  // Upper bound on the number of pairs compared, 0 for no bound.
  std::size_t max_pairs = 10000;
  // Added to estimate timestamps to find the ground truth poses.
  double offset = 0.0;
  // Multiplies the estimated relative translations.
  double scale = 1.0;
  // Seeds the random choice of pairs. The tool samples unseeded, so when it samples (more
  // candidate pairs than max_pairs) its figures vary from run to run and ours are repeatable.
  std::uint64_t seed = 0;
};

// One compared motion: estimate poses i -> j against the ground-truth poses closest in time.
struct RpePair {
  std::size_t first_index = 0;  // into the estimate
  std::size_t second_index = 0;
  double est_stamp_0 = 0.0;
  double est_stamp_1 = 0.0;
  double gt_stamp_0 = 0.0;
  double gt_stamp_1 = 0.0;
  double translational_error = 0.0;   // metres
  double rotational_error_deg = 0.0;  // degrees
};

struct RpeResult {
  std::vector<RpePair> pairs;
  ErrorStatistics translational;   // metres
  ErrorStatistics rotational_deg;  // degrees
};

// Relative pose error exactly as TUM evaluate_rpe.py computes it: for each pair (i, j) the error
// is inv(inv(E_j) E_i) * inv(G_j) G_i, where G are the ground-truth poses closest in time; pairs
// whose ground-truth stamps are more than twice the median ground-truth interval away are
// skipped. Throws util::Error when the timestamps barely overlap or fewer than 2 pairs remain.
RpeResult evaluateRpe(const core::Trajectory& ground_truth, const core::Trajectory& estimate,
                      const RpeOptions& options = {});

}  // namespace segslam::eval
