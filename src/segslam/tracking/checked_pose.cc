#include "segslam/tracking/checked_pose.h"

#include <cmath>

#include "segslam/optim/reprojection.h"

namespace segslam::tracking {

namespace {

bool agree(const geometry::Pose& a, const geometry::Pose& b, const CheckedPoseOptions& options) {
  const geometry::Pose difference = a * b.inverse();
  return difference.translation().norm() < options.agreement_m &&
         geometry::rotationAngle(difference) * 180.0 / M_PI < options.agreement_deg;
}

}  // namespace

optim::PoseOptimizationResult optimizePoseTrustingCheckedMatches(
    const optim::StereoIntrinsics& intrinsics, const geometry::Pose& initial_T_cw,
    const std::vector<optim::PoseObservation>& matches, const std::vector<bool>& provisional,
    const CheckedPoseOptions& options) {
  auto all = optim::optimizePose(intrinsics, initial_T_cw, matches);
  std::vector<optim::PoseObservation> checked;
  for (std::size_t k = 0; k < matches.size(); ++k) {
    if (!provisional[k]) checked.push_back(matches[k]);
  }
  if (checked.size() < static_cast<std::size_t>(options.min_checked) ||
      checked.size() == matches.size()) {
    return all;
  }
  const auto from_checked = optim::optimizePose(intrinsics, initial_T_cw, checked);
  if (from_checked.num_inliers < options.min_checked ||
      agree(all.T_cw, from_checked.T_cw, options)) {
    return all;
  }
  std::vector<optim::PoseObservation> kept;
  std::vector<std::size_t> kept_index;
  for (std::size_t k = 0; k < matches.size(); ++k) {
    const bool rejected =
        provisional[k] && !optim::isInlierObservation(intrinsics, matches[k].observation,
                                                      from_checked.T_cw * matches[k].point_w);
    if (rejected) continue;
    kept.push_back(matches[k]);
    kept_index.push_back(k);
  }
  const auto refined = optim::optimizePose(intrinsics, from_checked.T_cw, kept);
  optim::PoseOptimizationResult result{refined.T_cw, std::vector<bool>(matches.size(), false),
                                       refined.num_inliers};
  for (std::size_t j = 0; j < kept_index.size(); ++j)
    result.inlier[kept_index[j]] = refined.inlier[j];
  return result;
}

}  // namespace segslam::tracking
