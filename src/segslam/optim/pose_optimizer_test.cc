#include "segslam/optim/pose_optimizer.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "segslam/optim/optim_test_problems.h"

namespace segslam::optim {
namespace {

using testing::DepthMix;
using testing::perturbedPose;
using testing::PoseScene;
using testing::rotationErrorDegrees;
using testing::translationError;

struct Labelling {
  double outlier_recall;  // share of true outliers labelled outlier
  double inlier_kept;     // share of true inliers labelled inlier
};

Labelling compareLabels(const PoseScene& scene, const std::vector<bool>& inlier) {
  int outliers = 0, outliers_found = 0, inliers = 0, inliers_kept = 0;
  for (std::size_t i = 0; i < inlier.size(); ++i) {
    if (scene.is_outlier[i]) {
      ++outliers;
      outliers_found += inlier[i] ? 0 : 1;
    } else {
      ++inliers;
      inliers_kept += inlier[i] ? 1 : 0;
    }
  }
  return {static_cast<double>(outliers_found) / outliers,
          static_cast<double>(inliers_kept) / inliers};
}

void expectRecovered(const PoseScene& scene, const PoseOptimizationResult& result) {
  EXPECT_LT(translationError(result.T_cw, scene.T_cw), 0.005);
  EXPECT_LT(rotationErrorDegrees(result.T_cw, scene.T_cw), 0.2);
  const Labelling labels = compareLabels(scene, result.inlier);
  EXPECT_GT(labels.outlier_recall, 0.95);
  // The chi2 test at 95 % rejects about 5 % of genuine observations by design.
  EXPECT_GT(labels.inlier_kept, 0.9);
  EXPECT_EQ(result.num_inliers, std::count(result.inlier.begin(), result.inlier.end(), true));
}

class PoseOptimizerRecovery : public ::testing::TestWithParam<DepthMix> {};

TEST_P(PoseOptimizerRecovery, FromPerturbedPoseWithGrossOutliers) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    SCOPED_TRACE(trial);
    const PoseScene scene = testing::makePoseScene(rng, 300, 0.25, GetParam());
    const geometry::Pose initial = perturbedPose(rng, scene.T_cw, 0.10, 5.0 * M_PI / 180.0);
    expectRecovered(scene, optimizePose(scene.intrinsics, initial, scene.observations));
  }
}

INSTANTIATE_TEST_SUITE_P(DepthMixes, PoseOptimizerRecovery,
                         ::testing::Values(DepthMix::kAll, DepthMix::kNone, DepthMix::kHalf));

TEST(PoseOptimizer, PointsBehindTheCameraAreOutliers) {
  std::mt19937 rng(11);
  PoseScene scene = testing::makePoseScene(rng, 100, 0.0, DepthMix::kAll);
  // Mirror a few points through the camera centre: they land behind it.
  const Eigen::Vector3d centre = scene.T_cw.inverse().translation();
  for (int i = 0; i < 5; ++i) {
    Eigen::Vector3d& p_w = scene.observations[i].point_w;
    p_w = 2.0 * centre - p_w;
  }
  const PoseOptimizationResult result =
      optimizePose(scene.intrinsics, scene.T_cw, scene.observations);
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(result.inlier[i]) << i;
  EXPECT_LT(translationError(result.T_cw, scene.T_cw), 0.005);
}

TEST(PoseOptimizer, TooFewObservationsKeepTheInitialPose) {
  std::mt19937 rng(3);
  const PoseScene scene = testing::makePoseScene(rng, 2, 0.0, DepthMix::kAll);
  const geometry::Pose initial = perturbedPose(rng, scene.T_cw, 0.05, 0.02);
  const PoseOptimizationResult result = optimizePose(scene.intrinsics, initial, scene.observations);
  EXPECT_TRUE(result.T_cw.isApprox(initial));
  EXPECT_EQ(result.inlier.size(), 2u);
}

TEST(PoseOptimizer, NoObservationsIsANoOp) {
  const geometry::Pose initial = geometry::Pose::Identity();
  const PoseOptimizationResult result = optimizePose({}, initial, {});
  EXPECT_TRUE(result.T_cw.isApprox(initial));
  EXPECT_TRUE(result.inlier.empty());
  EXPECT_EQ(result.num_inliers, 0);
}

}  // namespace
}  // namespace segslam::optim
