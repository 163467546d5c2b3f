#include "segslam/optim/bundle_adjuster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>
#include <vector>

#include "segslam/optim/optim_test_scene.h"

namespace segslam::optim {
namespace {

using testing::perturbedPose;
using testing::rotationErrorDegrees;
using testing::translationError;

struct SceneOptions {
  int num_keyframes = 6;
  int num_points = 300;
  int covisibility_window = 3;  // a point is seen from keyframes within this many of its home
  double depth_share = 0.8;     // share of observations with depth
  // Share of the points seen at least 3 times whose observation in one keyframe is replaced by
  // a random pixel: a mismatch, as feature matching makes them.
  double mismatched_point_share = 0.0;
};

// Ground truth plus a problem that observes it with noise; keyframe 0 is fixed.
struct BaScene {
  std::vector<geometry::Pose> true_poses;
  std::vector<Eigen::Vector3d> true_points;
  std::vector<bool> is_outlier;  // per observation
  BundleAdjustmentProblem problem;
};

// Keyframes on an arc of radius 3 m, 8 degrees apart, all looking at its centre (0, 0, 3).
std::vector<geometry::Pose> keyframeArc(int num_keyframes) {
  constexpr double kRadius = 3.0;
  constexpr double kStep = 8.0 * M_PI / 180.0;
  const Eigen::Vector3d centre(0.0, 0.0, kRadius);
  std::vector<geometry::Pose> poses;
  for (int i = 0; i < num_keyframes; ++i) {
    const double angle = kStep * (i - 0.5 * (num_keyframes - 1));
    geometry::Pose T_wc = geometry::Pose::Identity();
    T_wc.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
    T_wc.translation() = centre - kRadius * T_wc.linear().col(2);
    poses.push_back(T_wc.inverse());
  }
  return poses;
}

bool isVisible(const StereoIntrinsics& k, const geometry::Pose& T_cw, const Eigen::Vector3d& p_w) {
  const Eigen::Vector3d p_c = T_cw * p_w;
  return isInFront(p_c) && testing::isInImage(predictMeasurement(k, p_c).head<2>());
}

// Adds a point seen from a random keyframe and the noisy observations of it from the
// keyframes around that one that see it.
void addPoint(std::mt19937& rng, const SceneOptions& options, BaScene& scene) {
  const StereoIntrinsics& k = scene.problem.intrinsics;
  const int home = std::uniform_int_distribution<int>(0, options.num_keyframes - 1)(rng);
  const Eigen::Vector3d p_w = testing::randomVisiblePoint(rng, k, scene.true_poses[home], 0.8, 6.0);
  const std::size_t point = scene.true_points.size();
  scene.true_points.push_back(p_w);
  std::bernoulli_distribution with_depth(options.depth_share);
  const std::size_t first_observation = scene.problem.observations.size();
  const int first = std::max(0, home - options.covisibility_window);
  const int last = std::min(options.num_keyframes - 1, home + options.covisibility_window);
  for (int j = first; j <= last; ++j) {
    const geometry::Pose& T_cw = scene.true_poses[j];
    if (!isVisible(k, T_cw, p_w)) continue;
    scene.problem.observations.push_back(
        {static_cast<std::size_t>(j), point,
         testing::noisyObservation(rng, k, T_cw, p_w, with_depth(rng))});
    scene.is_outlier.push_back(false);
  }
  const std::size_t num_observations = scene.problem.observations.size() - first_observation;
  if (num_observations >= 3 && std::bernoulli_distribution(options.mismatched_point_share)(rng)) {
    const std::size_t mismatched = first_observation + std::uniform_int_distribution<std::size_t>(
                                                           0, num_observations - 1)(rng);
    RgbdObservation& observation = scene.problem.observations[mismatched].observation;
    observation = testing::randomObservation(rng, k, observation.hasDepth());
    scene.is_outlier[mismatched] = true;
  }
}

BaScene makeScene(std::mt19937& rng, const SceneOptions& options) {
  BaScene scene;
  scene.true_poses = keyframeArc(options.num_keyframes);
  for (int i = 0; i < options.num_points; ++i) addPoint(rng, options, scene);
  for (std::size_t i = 0; i < scene.true_poses.size(); ++i) {
    scene.problem.keyframes.push_back({100 + i, scene.true_poses[i], i == 0});
  }
  for (std::size_t i = 0; i < scene.true_points.size(); ++i) {
    scene.problem.points.push_back({1000 + i, scene.true_points[i]});
  }
  return scene;
}

// Moves every free keyframe by `translation_m` / `angle_deg` and every point by about 3 cm per
// axis.
void perturb(std::mt19937& rng, BundleAdjustmentProblem& problem, double translation_m,
             double angle_deg) {
  for (BaKeyFrame& keyframe : problem.keyframes) {
    if (keyframe.fixed) continue;
    keyframe.T_cw = perturbedPose(rng, keyframe.T_cw, translation_m, angle_deg * M_PI / 180.0);
  }
  std::normal_distribution<double> noise(0.0, 0.03);
  for (BaPoint& point : problem.points) {
    point.position += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  }
}

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
  BaScene scene = makeScene(rng, {});
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
  SceneOptions options;
  options.mismatched_point_share = 0.2;
  BaScene scene = makeScene(rng, options);
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
  SceneOptions options;
  options.depth_share = 0.0;
  BaScene scene = makeScene(rng, options);
  scene.problem.keyframes[1].fixed = true;  // without depth, a second fixed keyframe sets scale
  perturb(rng, scene.problem, 0.02, 1.0);

  const BundleAdjustmentResult result = bundleAdjust(scene.problem);

  EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1);
  expectNearTruth(scene);
}

TEST(BundleAdjust, WithoutOutlierRemovalRunsTheRobustStageOnly) {
  std::mt19937 rng(24);
  BaScene scene = makeScene(rng, {});
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
  BaScene scene = makeScene(rng, {});
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
  SceneOptions options;
  options.num_keyframes = 56;
  options.num_points = 600;
  BaScene scene = makeScene(rng, options);
  perturb(rng, scene.problem, 0.01, 0.5);

  const BundleAdjustmentResult result = bundleAdjust(scene.problem);

  EXPECT_LT(result.final_cost, result.initial_cost);
  EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1);
}

TEST(BundleAdjust, IsDeterministic) {
  std::mt19937 rng(26);
  BaScene scene = makeScene(rng, {});
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
  BaScene scene = makeScene(rng, {});
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

void printTiming(int num_keyframes, int num_points) {
  std::mt19937 rng(28);
  SceneOptions options;
  options.num_keyframes = num_keyframes;
  options.num_points = num_points;
  options.mismatched_point_share = 0.05;
  BaScene scene = makeScene(rng, options);
  perturb(rng, scene.problem, 0.02, 1.0);
  const testing::Stopwatch stopwatch;
  const BundleAdjustmentResult result = bundleAdjust(scene.problem);
  std::cout << "[timing] bundleAdjust, " << num_keyframes << " keyframes, " << num_points
            << " points, " << scene.problem.observations.size()
            << " observations: " << stopwatch.cpuMs() << " ms CPU (" << stopwatch.wallMs()
            << " ms wall), " << result.iterations << " iterations\n";
  EXPECT_LT(normalisedRmsError(scene.problem, result.observation_inlier), 1.1);
}

// Not a pass/fail check on time (sanitiser builds are far slower): prints local BA's cost.
TEST(BundleAdjustTiming, LocalBundleAdjustmentSizes) {
  printTiming(10, 2000);
  printTiming(20, 3000);
}

}  // namespace
}  // namespace segslam::optim
