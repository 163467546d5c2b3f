#include "segslam/tracking/checked_pose.h"

#include <cmath>

#include "segslam/optim/reprojection.h"

namespace segslam::tracking {

namespace {

bool agree(const geometry::Pose& a, const geometry::Pose& b, double max_m, double max_deg) {
  const geometry::Pose difference = a * b.inverse();
  return difference.translation().norm() < max_m &&
         geometry::rotationAngle(difference) * 180.0 / M_PI < max_deg;
}

// The pose refined from `reference_T_cw` with the checked matches and the provisional ones that
// fit the reference (their chi2 within `chi2_scale` times the inlier threshold); nullopt when
// fewer than `min_kept` matches are left or fit the refined pose.
std::optional<optim::PoseOptimizationResult> refineFromReference(
    const optim::StereoIntrinsics& intrinsics, const geometry::Pose& reference_T_cw,
    const std::vector<optim::PoseObservation>& matches, const std::vector<bool>& provisional,
    double chi2_scale, int min_kept) {
  std::vector<optim::PoseObservation> kept;
  std::vector<std::size_t> kept_index;
  for (std::size_t k = 0; k < matches.size(); ++k) {
    const Eigen::Vector3d p_c = reference_T_cw * matches[k].point_w;
    const auto& observation = matches[k].observation;
    const bool fits =
        optim::isInFront(p_c) && optim::reprojectionChi2(intrinsics, observation, p_c) <=
                                     chi2_scale * optim::chi2Threshold(observation);
    if (provisional[k] && !fits) continue;
    kept.push_back(matches[k]);
    kept_index.push_back(k);
  }
  if (kept.size() < static_cast<std::size_t>(min_kept)) return std::nullopt;
  const auto refined = optim::optimizePose(intrinsics, reference_T_cw, kept);
  if (refined.num_inliers < min_kept) return std::nullopt;
  optim::PoseOptimizationResult result{refined.T_cw, std::vector<bool>(matches.size(), false),
                                       refined.num_inliers};
  for (std::size_t j = 0; j < kept_index.size(); ++j)
    result.inlier[kept_index[j]] = refined.inlier[j];
  return result;
}

}  // namespace

optim::PoseOptimizationResult optimizePoseTrustingCheckedMatches(
    const optim::StereoIntrinsics& intrinsics, const geometry::Pose& initial_T_cw,
    const std::vector<optim::PoseObservation>& matches, const std::vector<bool>& provisional,
    const std::optional<geometry::Pose>& predicted_T_cw, const CheckedPoseOptions& options) {
  auto all = optim::optimizePose(intrinsics, initial_T_cw, matches);
  std::vector<optim::PoseObservation> checked;
  for (std::size_t k = 0; k < matches.size(); ++k) {
    if (!provisional[k]) checked.push_back(matches[k]);
  }
  if (checked.size() == matches.size()) return all;
  if (checked.size() >= static_cast<std::size_t>(options.min_checked)) {
    const auto from_checked = optim::optimizePose(intrinsics, initial_T_cw, checked);
    if (from_checked.num_inliers < options.min_checked ||
        agree(all.T_cw, from_checked.T_cw, options.agreement_m, options.agreement_deg)) {
      return all;
    }
    return refineFromReference(intrinsics, from_checked.T_cw, matches, provisional, 1.0, 0).value();
  }
  if (!predicted_T_cw || agree(all.T_cw, *predicted_T_cw, options.predicted_agreement_m,
                               options.predicted_agreement_deg)) {
    return all;
  }
  return refineFromReference(intrinsics, *predicted_T_cw, matches, provisional,
                             options.predicted_inlier_chi2_scale, options.min_checked)
      .value_or(all);
}

}  // namespace segslam::tracking
