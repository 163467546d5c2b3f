#include "segslam/optim/bundle_adjuster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "segslam/optim/optim_test_problems.h"

namespace segslam::optim {
namespace {

using testing::BaScene;
using testing::BaSceneOptions;
using testing::perturb;
using testing::perturbedPose;
using testing::rotationErrorDegrees;
using testing::translationError;

// sqrt(sum chi2 / sum dof) over the observations flagged `use`: about 1 at the noise level.
double normalisedRmsError(const BundleAdjustmentProblem& problem, const std::vector<bool>& use) {
  double chi2 = 0.0;
  int dof = 0;
  for (std::size_t i = 0; i < problem.observations.size(); ++i) {
    if (!use[i]) continue;
    const BaObservation& observation = problem.observations[i];
    const Eigen::Vector3d p_c =
        problem.keyframes[observation.keyframe].T_cw * problem.points[observation.point].position;
    chi2 += reprojectionChi2(problem.intrinsics, observation.observation, p_c);
    dof += observation.observation.hasDepth() ? 3 : 2;
  }
  return std::sqrt(chi2 / dof);
}

// The scene's own uncertainty bounds how close to the truth BA can get: with 1 px noise the
// far end of the arc has a standard deviation of about 7 mm and 0.14 deg (Ceres' covariance
// at the optimum), most of it along the slide-and-turn motion that keeps the points in view.
// These bounds are about 4 sigma.
void expectNearTruth(const BaScene& scene) {
  for (std::size_t i = 0; i < scene.true_poses.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_LT(translationError(scene.problem.keyframes[i].T_cw, scene.true_poses[i]), 0.03);
    EXPECT_LT(rotationErrorDegrees(scene.problem.keyframes[i].T_cw, scene.true_poses[i]), 0.6);
  }
}

// The optimum that BA reaches when started at the ground truth: the reference for convergence.
BundleAdjustmentProblem optimumFromTruth(const BaScene& scene) {
  BundleAdjustmentProblem problem = scene.problem;
  for (std::size_t i = 0; i < problem.keyframes.size(); ++i) {
    problem.keyframes[i].T_cw = scene.true_poses[i];
  }
  for (std::size_t i = 0; i < problem.points.size(); ++i) {
    problem.points[i].position = scene.true_points[i];
  }
  bundleAdjust(problem);
  return problem;
}

TEST(BundleAdjust, ConvergesToTheOptimumAtTheNoiseLevel) {
  std::mt19937 rng(21);
  BaScene scene = testing::makeBaScene(rng, {});
  const BundleAdjustmentProblem optimum = optimumFromTruth(scene);
  perturb(rng, scene.problem, 0.05, 2.0);
  const std::vector<bool> all(scene.problem.observations.size(), true);
  const double error_before = normalisedRmsError(scene.problem, all);

  const BundleAdjustmentResult result = bundleAdjust(scene.problem);

  EXPECT_GT(error_before, 5.0);
  EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1);
  EXPECT_LT(result.final_cost, result.initial_cost);
  EXPECT_GT(result.iterations, 0);
  EXPECT_TRUE(scene.problem.keyframes[0].T_cw.isApprox(scene.true_poses[0], 0.0));  // fixed
  for (std::size_t i = 0; i < optimum.keyframes.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_LT(translationError(scene.problem.keyframes[i].T_cw, optimum.keyframes[i].T_cw), 1e-4);
    EXPECT_LT(rotationErrorDegrees(scene.problem.keyframes[i].T_cw, optimum.keyframes[i].T_cw),
              1e-3);
  }
  expectNearTruth(scene);
}

TEST(BundleAdjust, FlagsMismatchedObservations) {
  std::mt19937 rng(22);
  BaSceneOptions options;
  options.mismatched_point_share = 0.2;
  BaScene scene = testing::makeBaScene(rng, options);
  perturb(rng, scene.problem, 0.02, 1.0);

  const BundleAdjustmentResult result = bundleAdjust(scene.problem);

  int outliers = 0, outliers_found = 0, inliers = 0, inliers_kept = 0;
  for (std::size_t i = 0; i < scene.is_outlier.size(); ++i) {
    if (scene.is_outlier[i]) {
      ++outliers;
      outliers_found += result.observation_inlier[i] ? 0 : 1;
    } else {
      ++inliers;
      inliers_kept += result.observation_inlier[i] ? 1 : 0;
    }
  }
  ASSERT_GT(outliers, 30);
  EXPECT_GT(static_cast<double>(outliers_found) / outliers, 0.95);
  // The chi2 test at 95 % rejects about 5 % of genuine observations by design.
  EXPECT_GT(static_cast<double>(inliers_kept) / inliers, 0.9);
  EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1);
  expectNearTruth(scene);
}

TEST(BundleAdjust, MonocularObservationsWithTwoFixedKeyFrames) {
  std::mt19937 rng(23);
  BaSceneOptions options;
  options.depth_share = 0.0;
  BaScene scene = testing::makeBaScene(rng, options);
  scene.problem.keyframes[1].fixed = true;  // without depth, a second fixed keyframe sets scale
  perturb(rng, scene.problem, 0.02, 1.0);

  const BundleAdjustmentResult result = bundleAdjust(scene.problem);

  EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1);
  expectNearTruth(scene);
}

TEST(BundleAdjust, WithoutOutlierRemovalRunsTheRobustStageOnly) {
  std::mt19937 rng(24);
  BaScene scene = testing::makeBaScene(rng, {});
  perturb(rng, scene.problem, 0.02, 1.0);
  BundleAdjustmentOptions options;
  options.remove_outliers = false;
  options.iterations_first = 20;

  const BundleAdjustmentResult result = bundleAdjust(scene.problem, options);

  EXPECT_LE(result.iterations, 20);
  EXPECT_EQ(result.observation_inlier.size(), scene.problem.observations.size());
  expectNearTruth(scene);
}

TEST(BundleAdjust, PointBehindItsCameraIsAnOutlierAndDoesNotBreakTheSolve) {
  std::mt19937 rng(25);
  BaScene scene = testing::makeBaScene(rng, {});
  // Mirror the first observation's point through its camera's centre: it lands behind it.
  const BaObservation& observation = scene.problem.observations.front();
  const Eigen::Vector3d centre =
      scene.problem.keyframes[observation.keyframe].T_cw.inverse().translation();
  Eigen::Vector3d& point = scene.problem.points[observation.point].position;
  point = 2.0 * centre - point;

  const BundleAdjustmentResult result = bundleAdjust(scene.problem);

  EXPECT_FALSE(result.observation_inlier.front());
  expectNearTruth(scene);
}

// Beyond 50 free keyframes the solver switches from dense to sparse Schur complement.
TEST(BundleAdjust, ManyKeyFramesAlsoConvergeToTheNoiseLevel) {
  std::mt19937 rng(29);
  BaSceneOptions options;
  options.num_keyframes = 56;
  options.num_points = 600;
  BaScene scene = testing::makeBaScene(rng, options);
  perturb(rng, scene.problem, 0.01, 0.5);

  const BundleAdjustmentResult result = bundleAdjust(scene.problem);

  EXPECT_LT(result.final_cost, result.initial_cost);
  EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1);
}

TEST(BundleAdjust, IsDeterministic) {
  std::mt19937 rng(26);
  BaScene scene = testing::makeBaScene(rng, {});
  perturb(rng, scene.problem, 0.02, 1.0);
  BundleAdjustmentProblem copy = scene.problem;
  bundleAdjust(scene.problem);
  bundleAdjust(copy);
  for (std::size_t i = 0; i < copy.keyframes.size(); ++i) {
    EXPECT_TRUE(copy.keyframes[i].T_cw.isApprox(scene.problem.keyframes[i].T_cw, 0.0));
  }
  for (std::size_t i = 0; i < copy.points.size(); ++i) {
    EXPECT_EQ(copy.points[i].position, scene.problem.points[i].position);
  }
}

TEST(BundleAdjust, EmptyProblemAndAllFixedKeyFramesAreHandled) {
  BundleAdjustmentProblem empty;
  EXPECT_TRUE(bundleAdjust(empty).observation_inlier.empty());

  std::mt19937 rng(27);
  BaScene scene = testing::makeBaScene(rng, {});
  for (BaKeyFrame& keyframe : scene.problem.keyframes) keyframe.fixed = true;
  const BundleAdjustmentResult result = bundleAdjust(scene.problem);
  EXPECT_EQ(result.observation_inlier.size(), scene.problem.observations.size());
  for (std::size_t i = 0; i < scene.true_poses.size(); ++i) {
    EXPECT_TRUE(scene.problem.keyframes[i].T_cw.isApprox(scene.true_poses[i], 0.0));
  }
}

TEST(BundleAdjust, RejectsOutOfRangeIndices) {
  BundleAdjustmentProblem problem;
  problem.keyframes.push_back({});
  problem.observations.push_back({0, 0, {}});  // there is no point 0
  EXPECT_THROW(bundleAdjust(problem), std::invalid_argument);
}

// Problems the size local mapping meets (10 keyframes / 2000 points, 20 / 3000), with mismatches:
// still the noise level. Their solve time is bench/optimizer.cc's.
TEST(BundleAdjust, LocalMappingSizedProblemsWithMismatchesConverge) {
  std::mt19937 rng(28);
  for (const auto& [num_keyframes, num_points] : {std::pair{10, 2000}, std::pair{20, 3000}}) {
    BaSceneOptions options;
    options.num_keyframes = num_keyframes;
    options.num_points = num_points;
    options.mismatched_point_share = 0.05;
    BaScene scene = testing::makeBaScene(rng, options);
    perturb(rng, scene.problem, 0.02, 1.0);
    const BundleAdjustmentResult result = bundleAdjust(scene.problem);
    EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1) << num_keyframes;
  }
}

}  // namespace
}  // namespace segslam::optim
