#pragma once

// Whole optimisation problems with their ground truth, for the optimiser tests and bench/optimizer
// (header-only, never linked into the library): a keyframe arc whose points are seen with noise
// (bundle adjustment) and one frame's observations with gross mismatches (pose optimisation).

#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

#include "segslam/optim/bundle_adjuster.h"
#include "segslam/optim/optim_test_scene.h"
#include "segslam/optim/pose_optimizer.h"

namespace segslam::optim::testing {

struct BaSceneOptions {
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
inline std::vector<geometry::Pose> keyframeArc(int num_keyframes) {
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

inline bool isVisible(const StereoIntrinsics& k, const geometry::Pose& T_cw,
                      const Eigen::Vector3d& p_w) {
  const Eigen::Vector3d p_c = T_cw * p_w;
  return isInFront(p_c) && isInImage(predictMeasurement(k, p_c).head<2>());
}

// Adds a point seen from a random keyframe and the noisy observations of it from the
// keyframes around that one that see it.
inline void addPoint(std::mt19937& rng, const BaSceneOptions& options, BaScene& scene) {
  const StereoIntrinsics& k = scene.problem.intrinsics;
  const int home = std::uniform_int_distribution<int>(0, options.num_keyframes - 1)(rng);
  const Eigen::Vector3d p_w = randomVisiblePoint(rng, k, scene.true_poses[home], 0.8, 6.0);
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
        {static_cast<std::size_t>(j), point, noisyObservation(rng, k, T_cw, p_w, with_depth(rng))});
    scene.is_outlier.push_back(false);
  }
  const std::size_t num_observations = scene.problem.observations.size() - first_observation;
  if (num_observations >= 3 && std::bernoulli_distribution(options.mismatched_point_share)(rng)) {
    const std::size_t mismatched = first_observation + std::uniform_int_distribution<std::size_t>(
                                                           0, num_observations - 1)(rng);
    RgbdObservation& observation = scene.problem.observations[mismatched].observation;
    observation = randomObservation(rng, k, observation.hasDepth());
    scene.is_outlier[mismatched] = true;
  }
}

inline BaScene makeBaScene(std::mt19937& rng, const BaSceneOptions& options) {
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
inline void perturb(std::mt19937& rng, BundleAdjustmentProblem& problem, double translation_m,
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

enum class DepthMix { kAll, kNone, kHalf };

// A frame's observations of random visible points, a share of them gross mismatches.
struct PoseScene {
  StereoIntrinsics intrinsics;
  geometry::Pose T_cw;
  std::vector<PoseObservation> observations;
  std::vector<bool> is_outlier;  // ground truth
};

inline PoseScene makePoseScene(std::mt19937& rng, int num_points, double outlier_ratio,
                               DepthMix depth) {
  PoseScene scene;
  scene.T_cw = geometry::poseFromTranslationQuaternion({0.3, -0.2, 1.0},
                                                       Eigen::Quaterniond(0.95, 0.1, -0.2, 0.05));
  std::bernoulli_distribution outlier(outlier_ratio);
  std::bernoulli_distribution coin(0.5);
  for (int i = 0; i < num_points; ++i) {
    const Eigen::Vector3d p_w = randomVisiblePoint(rng, scene.intrinsics, scene.T_cw, 0.8, 6.0);
    const bool with_depth = depth == DepthMix::kAll || (depth == DepthMix::kHalf && coin(rng));
    const bool is_outlier = outlier(rng);
    const RgbdObservation observation =
        is_outlier ? randomObservation(rng, scene.intrinsics, with_depth)
                   : noisyObservation(rng, scene.intrinsics, scene.T_cw, p_w, with_depth);
    scene.observations.push_back({p_w, observation});
    scene.is_outlier.push_back(is_outlier);
  }
  return scene;
}

}  // namespace segslam::optim::testing
