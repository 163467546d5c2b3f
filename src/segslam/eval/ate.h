#pragma once

#include <cstddef>
#include <vector>

#include "segslam/core/trajectory.h"
#include "segslam/eval/alignment.h"
#include "segslam/eval/statistics.h"

namespace segslam::eval {

// Options of TUM evaluate_ate.py, plus the choice of alignment.
struct AteOptions {
  // Largest |t_gt - (t_est + offset)| for two poses to be matched, seconds.
  double max_difference = 0.02;
  // Added to estimate timestamps before matching, seconds.
  double offset = 0.0;
  // Multiplies the estimated positions before alignment.
  double scale = 1.0;
  AlignmentMethod alignment = AlignmentMethod::kSe3;
};

// One matched pose: the estimate's aligned position against the ground truth's.
struct AtePair {
  std::size_t gt_index = 0;
  std::size_t est_index = 0;
  double gt_stamp = 0.0;
  double est_stamp = 0.0;
  double error = 0.0;  // metres
};

struct AteResult {
  std::vector<AtePair> pairs;  // in ground-truth time order
  // Maps the (scaled) estimate onto the ground truth.
  Alignment alignment;
  ErrorStatistics statistics;  // metres
  // The whole estimate, positions scaled by AteOptions::scale and then aligned.
  core::Trajectory aligned_estimate;
};

// Absolute trajectory error as TUM evaluate_ate.py: poses matched by timestamp (associate.py),
// estimated positions aligned onto the ground-truth ones, error = distance per matched pose.
// Throws util::Error when fewer than 2 poses match.
AteResult evaluateAte(const core::Trajectory& ground_truth, const core::Trajectory& estimate,
                      const AteOptions& options = {});

// The ground truth moved into the estimate's frame by undoing the ATE alignment (and the
// estimate scale), so that it overlays the raw estimate, e.g. in the map viewer.
core::Trajectory groundTruthInEstimateFrame(const core::Trajectory& ground_truth,
                                            const AteResult& ate, const AteOptions& options);

}  // namespace segslam::eval
