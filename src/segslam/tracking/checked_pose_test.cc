#include "segslam/tracking/checked_pose.h"

#include <gtest/gtest.h>

#include <random>

#include "segslam/optim/optim_test_scene.h"

namespace segslam::tracking {
namespace {

using optim::testing::noisyObservation;
using optim::testing::randomVisiblePoint;
using optim::testing::translationError;

// A frame's matches: checked static points, provisional static points (a new keyframe's), and
// many provisional points on a person 1.5-2.5 m away who has stepped 6 cm sideways since the
// keyframe that made them: their map positions are where he stood.
struct StepAsideScene {
  optim::StereoIntrinsics intrinsics;
  geometry::Pose T_cw = geometry::poseFromTranslationQuaternion(
      {0.1, -0.05, 0.2}, Eigen::Quaterniond(0.99, 0.05, -0.08, 0.02));
  std::vector<optim::PoseObservation> matches;
  std::vector<bool> provisional;
  std::vector<bool> on_person;

  StepAsideScene(int checked_static, int provisional_static, int person) {
    std::mt19937 rng(7);
    const Eigen::Vector3d step_w = T_cw.linear().transpose() * Eigen::Vector3d(0.06, 0.0, 0.0);
    auto add = [&](double near, double far, bool is_provisional, bool is_person) {
      const Eigen::Vector3d p_w = randomVisiblePoint(rng, intrinsics, T_cw, near, far);
      const Eigen::Vector3d seen_at = is_person ? Eigen::Vector3d(p_w + step_w) : p_w;
      matches.push_back({p_w, noisyObservation(rng, intrinsics, T_cw, seen_at, true)});
      provisional.push_back(is_provisional);
      on_person.push_back(is_person);
    };
    for (int i = 0; i < checked_static; ++i) add(1.0, 4.0, false, false);
    for (int i = 0; i < provisional_static; ++i) add(1.0, 4.0, true, false);
    for (int i = 0; i < person; ++i) add(1.5, 2.5, true, true);
  }
};

// Inlier counts of a result over the person's matches and the provisional static ones.
struct Labels {
  int person = 0;
  int person_inliers = 0;
  int static_provisional = 0;
  int static_provisional_inliers = 0;
};

Labels labels(const StepAsideScene& scene, const optim::PoseOptimizationResult& result) {
  Labels counts;
  for (std::size_t k = 0; k < scene.matches.size(); ++k) {
    const int inlier = result.inlier[k] ? 1 : 0;
    if (scene.on_person[k]) {
      ++counts.person;
      counts.person_inliers += inlier;
    } else if (scene.provisional[k]) {
      ++counts.static_provisional;
      counts.static_provisional_inliers += inlier;
    }
  }
  return counts;
}

TEST(CheckedPose, ProvisionalPointsOnAMovingPersonDoNotDecideThePose) {
  const StepAsideScene scene(60, 40, 200);
  std::mt19937 rng(3);
  const geometry::Pose guess = optim::testing::perturbedPose(rng, scene.T_cw, 0.01, 0.005);
  const auto all_together = optim::optimizePose(scene.intrinsics, guess, scene.matches);
  ASSERT_GT(translationError(all_together.T_cw, scene.T_cw), 0.01)
      << "the scene must be one where the person drags a joint estimate along";

  const auto result =
      optimizePoseTrustingCheckedMatches(scene.intrinsics, guess, scene.matches, scene.provisional);
  EXPECT_LT(translationError(result.T_cw, scene.T_cw), 0.005);
  const Labels counts = labels(scene, result);
  EXPECT_LT(counts.person_inliers, 0.05 * counts.person);
  EXPECT_GT(counts.static_provisional_inliers, 0.9 * counts.static_provisional);
  EXPECT_EQ(result.num_inliers, std::count(result.inlier.begin(), result.inlier.end(), true));
}

TEST(CheckedPose, WhenCheckedAndProvisionalMatchesAgreeThePoseIsThatOfAll) {
  const StepAsideScene scene(60, 100, 0);
  std::mt19937 rng(3);
  const geometry::Pose guess = optim::testing::perturbedPose(rng, scene.T_cw, 0.01, 0.005);
  const auto all_together = optim::optimizePose(scene.intrinsics, guess, scene.matches);
  const auto result =
      optimizePoseTrustingCheckedMatches(scene.intrinsics, guess, scene.matches, scene.provisional);
  EXPECT_TRUE(result.T_cw.isApprox(all_together.T_cw));
  EXPECT_EQ(result.inlier, all_together.inlier);
}

// A view mostly filled by people: two dozen checked matches still outvote 200 provisional ones on
// a person who stepped aside.
TEST(CheckedPose, AFewDozenCheckedMatchesOutvoteAPerson) {
  const StepAsideScene scene(24, 20, 200);
  std::mt19937 rng(3);
  const geometry::Pose guess = optim::testing::perturbedPose(rng, scene.T_cw, 0.01, 0.005);
  const auto all_together = optim::optimizePose(scene.intrinsics, guess, scene.matches);
  ASSERT_GT(translationError(all_together.T_cw, scene.T_cw), 0.01);
  const auto result =
      optimizePoseTrustingCheckedMatches(scene.intrinsics, guess, scene.matches, scene.provisional);
  EXPECT_LT(translationError(result.T_cw, scene.T_cw), 0.005);
  EXPECT_LT(labels(scene, result).person_inliers, 10);
}

TEST(CheckedPose, WithoutAPredictionTooFewCheckedMatchesLeaveThePoseToAllMatches) {
  const StepAsideScene scene(CheckedPoseOptions{}.min_checked - 5, 40, 100);
  const auto all_together = optim::optimizePose(scene.intrinsics, scene.T_cw, scene.matches);
  const auto result = optimizePoseTrustingCheckedMatches(scene.intrinsics, scene.T_cw,
                                                         scene.matches, scene.provisional);
  EXPECT_TRUE(result.T_cw.isApprox(all_together.T_cw));
  EXPECT_EQ(result.inlier, all_together.inlier);
}

// People fill the view: a handful of checked matches, the rest a new keyframe's provisional points,
// most of them on a person who stepped aside. The camera's predicted motion, a little off as a
// hand-held camera's is, tells the static ones from his.
TEST(CheckedPose, WithTooFewCheckedMatchesThePredictedPoseTellsThePersonApart) {
  const StepAsideScene scene(CheckedPoseOptions{}.min_checked - 15, 60, 200);
  std::mt19937 rng(3);
  const geometry::Pose predicted = optim::testing::perturbedPose(rng, scene.T_cw, 0.008, 0.004);
  const auto all_together = optim::optimizePose(scene.intrinsics, predicted, scene.matches);
  ASSERT_GT(translationError(all_together.T_cw, scene.T_cw), 0.02);

  const auto result = optimizePoseTrustingCheckedMatches(scene.intrinsics, predicted, scene.matches,
                                                         scene.provisional, predicted);
  EXPECT_LT(translationError(result.T_cw, scene.T_cw), 0.005);
  const Labels counts = labels(scene, result);
  EXPECT_LT(counts.person_inliers, 0.05 * counts.person);
  EXPECT_GT(counts.static_provisional_inliers, 0.9 * counts.static_provisional);
}

TEST(CheckedPose, APredictionThatAgreesWithAllMatchesLeavesThePoseToThem) {
  const StepAsideScene scene(CheckedPoseOptions{}.min_checked - 15, 100, 0);
  std::mt19937 rng(3);
  const geometry::Pose predicted = optim::testing::perturbedPose(rng, scene.T_cw, 0.008, 0.004);
  const auto all_together = optim::optimizePose(scene.intrinsics, predicted, scene.matches);
  const auto result = optimizePoseTrustingCheckedMatches(scene.intrinsics, predicted, scene.matches,
                                                         scene.provisional, predicted);
  EXPECT_TRUE(result.T_cw.isApprox(all_together.T_cw));
  EXPECT_EQ(result.inlier, all_together.inlier);
}

}  // namespace
}  // namespace segslam::tracking
