#pragma once

#include <optional>
#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/optim/pose_optimizer.h"

namespace segslam::tracking {

struct CheckedPoseOptions {
  // The checked matches decide only when at least this many of them fit their own pose. When
  // people fill the view and the keyframes' own masks are late, the checked matches left are few:
  // fr1_p2_s12_fast with network outputs 10 frames late had 6-40 checked among 47-145 inliers
  // while provisional points on a walker dragged the pose 0.1 m (`--deterministic
  // --network-interval 9 --network-latency 10`: ATE 0.0159 m at 30, 0.0116 at 20; runs whose
  // masks are on time do not change).
  int min_checked = 20;
  // Poses from all matches and from the checked ones alone that differ by less than this agree:
  // the provisional matches are then as good as the checked ones (a static scene, or a person
  // already masked), and the pose from all of them stands.
  double agreement_m = 0.005;
  double agreement_deg = 0.3;
  // With too few checked matches, the constant-velocity prediction stands in for their pose:
  // provisional matches that a person carries move with him, static ones stay where the camera's
  // motion puts them. The prediction is looser than a checked pose (the camera accelerates), so
  // its agreement and its inlier test are wider. At 1 degree the first map's frames (all points
  // provisional, the velocity from one or two frames) were refined from the prediction with a
  // third of their inliers: fr1_near_p1_s41 from frame 115 lost the map in 2 of 5 runs.
  double predicted_agreement_m = 0.02;
  double predicted_agreement_deg = 2.5;
  double predicted_inlier_chi2_scale = 4.0;
};

// Motion-only pose optimisation (optim::optimizePose) over matches of which some are
// provisional: to map points that no keyframe's own mask has checked yet (MapPoint::provisional).
// A person whom the masks missed can carry as many provisional points as the static scene has
// checked ones, all moving with him: estimated together, they drag the pose along. When the pose
// of the checked matches alone disagrees with that of all matches, the provisional matches that
// do not fit it are outliers, and the pose is refined from the checked pose with the rest.
// `provisional` has one flag per match; inlier flags of the result are per match.
// `predicted_T_cw`: the pose the camera's recent motion predicts, if known.
[[nodiscard]] optim::PoseOptimizationResult optimizePoseTrustingCheckedMatches(
    const optim::StereoIntrinsics& intrinsics, const geometry::Pose& initial_T_cw,
    const std::vector<optim::PoseObservation>& matches, const std::vector<bool>& provisional,
    const std::optional<geometry::Pose>& predicted_T_cw = std::nullopt,
    const CheckedPoseOptions& options = {});

}  // namespace segslam::tracking
