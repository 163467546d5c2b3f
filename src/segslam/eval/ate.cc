#include "segslam/eval/ate.h"

#include <fmt/format.h>

#include "segslam/io/timestamp_association.h"
#include "segslam/util/error.h"

namespace segslam::eval {

namespace {

core::Trajectory alignTrajectory(const core::Trajectory& estimate, double scale,
                                 const Alignment& alignment) {
  core::Trajectory aligned;
  for (const auto& pose : estimate.poses()) {
    geometry::Pose scaled = pose.T_wc;
    scaled.translation() *= scale;
    aligned.append(pose.timestamp, alignment.apply(scaled));
  }
  return aligned;
}

}  // namespace

AteResult evaluateAte(const core::Trajectory& ground_truth, const core::Trajectory& estimate,
                      const AteOptions& options) {
  const auto matches = io::associateTimestamps(ground_truth.timestamps(), estimate.timestamps(),
                                               options.max_difference, options.offset);
  if (matches.size() < 2) {
    throw util::Error(fmt::format(
        "only {} estimated pose(s) match a ground-truth timestamp within {} s (offset {} s); "
        "need at least 2",
        matches.size(), options.max_difference, options.offset));
  }
  const auto n = static_cast<Eigen::Index>(matches.size());
  Eigen::Matrix3Xd gt_positions(3, n);
  Eigen::Matrix3Xd est_positions(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto [i, j] = matches[static_cast<std::size_t>(k)];
    gt_positions.col(k) = ground_truth[i].T_wc.translation();
    est_positions.col(k) = options.scale * estimate[j].T_wc.translation();
  }

  AteResult result;
  result.alignment = alignPoints(est_positions, gt_positions, options.alignment);
  std::vector<double> errors;
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto [i, j] = matches[static_cast<std::size_t>(k)];
    const double error =
        (result.alignment.apply(Eigen::Vector3d(est_positions.col(k))) - gt_positions.col(k))
            .norm();
    result.pairs.push_back({i, j, ground_truth[i].timestamp, estimate[j].timestamp, error});
    errors.push_back(error);
  }
  result.statistics = computeStatistics(errors);
  result.aligned_estimate = alignTrajectory(estimate, options.scale, result.alignment);
  return result;
}

core::Trajectory groundTruthInEstimateFrame(const core::Trajectory& ground_truth,
                                            const AteResult& ate, const AteOptions& options) {
  Alignment to_estimate = ate.alignment.inverse();
  to_estimate.scale /= options.scale;
  to_estimate.translation /= options.scale;
  core::Trajectory moved;
  for (const auto& pose : ground_truth.poses()) {
    moved.append(pose.timestamp, to_estimate.apply(pose.T_wc));
  }
  return moved;
}

}  // namespace segslam::eval
