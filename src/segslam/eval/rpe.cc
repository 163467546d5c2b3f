#include "segslam/eval/rpe.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "segslam/eval/closest_index.h"
#include "segslam/util/error.h"

namespace segslam::eval {

namespace {

// The tool's sanity check: mapping estimate stamps to the closest ground-truth stamp and back
// must reach at least two distinct estimate poses, or the files do not belong together.
void requireTimestampOverlap(const std::vector<double>& gt_stamps,
                             const std::vector<double>& est_stamps, double offset) {
  std::set<std::size_t> returned;
  for (const double t_est : est_stamps) {
    const double t_gt = gt_stamps[findClosestIndex(gt_stamps, t_est + offset)];
    returned.insert(findClosestIndex(est_stamps, t_gt - offset));
  }
  if (returned.size() < 2) {
    throw util::Error(
        "ground truth and estimate timestamps barely overlap (fewer than 2 poses); are these the "
        "right files, and is the offset right?");
  }
}

std::vector<PosePair> candidatePairs(const core::Trajectory& estimate, const RpeOptions& options,
                                     std::mt19937_64& rng) {
  if (!options.fixed_delta) return allOrRandomPairs(estimate.size(), options.max_pairs, rng);
  const auto index = deltaIndex(estimate, options.delta_unit);
  auto pairs = limitPairs(fixedDeltaPairs(index, options.delta), options.max_pairs, rng);
  // A short estimate (a run of a few frames) has no pairs a whole delta apart: say so, rather than
  // blame the ground truth below.
  if (pairs.size() < 2) {
    throw util::Error(fmt::format(
        "the estimate spans {:.3f} s ({} poses) and has {} pose pair(s) {:g} {} apart (pairs "
        "ending at its last pose do not count, as in the TUM tool); need at least 2",
        estimate[estimate.size() - 1].timestamp - estimate[0].timestamp, estimate.size(),
        pairs.size(), options.delta, deltaUnitName(options.delta_unit)));
  }
  return pairs;
}

double medianInterval(const std::vector<double>& stamps) {
  std::vector<double> intervals;
  for (std::size_t k = 1; k < stamps.size(); ++k) intervals.push_back(stamps[k] - stamps[k - 1]);
  return median(intervals);
}

// inv(inv(E_j) E_i) * inv(G_j) G_i, the estimated motion scaled as the tool does.
geometry::Pose motionError(const geometry::Pose& est_i, const geometry::Pose& est_j,
                           const geometry::Pose& gt_i, const geometry::Pose& gt_j, double scale) {
  geometry::Pose est_motion = est_j.inverse() * est_i;
  est_motion.translation() *= scale;
  return est_motion.inverse() * (gt_j.inverse() * gt_i);
}

ErrorStatistics statisticsOf(const std::vector<RpePair>& pairs, double RpePair::*field) {
  std::vector<double> values;
  values.reserve(pairs.size());
  for (const auto& pair : pairs) values.push_back(pair.*field);
  return computeStatistics(values);
}

}  // namespace

RpeResult evaluateRpe(const core::Trajectory& ground_truth, const core::Trajectory& estimate,
                      const RpeOptions& options) {
  if (ground_truth.size() < 2 || estimate.size() < 2) {
    throw util::Error("RPE needs at least 2 poses in both ground truth and estimate");
  }
  const auto gt_stamps = ground_truth.timestamps();
  const auto est_stamps = estimate.timestamps();
  requireTimestampOverlap(gt_stamps, est_stamps, options.offset);

  std::mt19937_64 rng(options.seed);
  const double max_gt_time_difference = 2.0 * medianInterval(gt_stamps);
  RpeResult result;
  for (const auto& [i, j] : candidatePairs(estimate, options, rng)) {
    const double target_0 = est_stamps[i] + options.offset;
    const double target_1 = est_stamps[j] + options.offset;
    const std::size_t g0 = findClosestIndex(gt_stamps, target_0);
    const std::size_t g1 = findClosestIndex(gt_stamps, target_1);
    if (std::abs(gt_stamps[g0] - target_0) > max_gt_time_difference ||
        std::abs(gt_stamps[g1] - target_1) > max_gt_time_difference) {
      continue;
    }
    const auto error = motionError(estimate[i].T_wc, estimate[j].T_wc, ground_truth[g0].T_wc,
                                   ground_truth[g1].T_wc, options.scale);
    result.pairs.push_back({i, j, est_stamps[i], est_stamps[j], gt_stamps[g0], gt_stamps[g1],
                            error.translation().norm(),
                            geometry::rotationAngle(error) * 180.0 / std::numbers::pi});
  }
  if (result.pairs.size() < 2) {
    throw util::Error(
        fmt::format("only {} RPE pose pair(s) have ground truth within {:.3f} s; need at least 2",
                    result.pairs.size(), max_gt_time_difference));
  }
  result.translational = statisticsOf(result.pairs, &RpePair::translational_error);
  result.rotational_deg = statisticsOf(result.pairs, &RpePair::rotational_error_deg);
  return result;
}

}  // namespace segslam::eval
