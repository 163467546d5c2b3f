#include "segslam/eval/trajectory_evaluation.h"

#include <gtest/gtest.h>

#include "segslam/eval/test_trajectories.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::eval {
namespace {

constexpr double kMetreTolerance = 1e-4;
constexpr double kDegreeTolerance = 1e-3;

// Figures printed by the TUM RGB-D tools (evaluate_ate.py; evaluate_rpe.py --fixed_delta) for
// DynaSLAM on fr3/walking_xyz.
TEST(EvalReference, MatchesTheTumToolsWithOneSecondDelta) {
  SEGSLAM_REQUIRE_SHARED(dir, "reference_trajectories");
  const auto evaluation = evaluateTrajectoryFiles(dir / "walking_xyz_groundtruth.txt",
                                                  dir / "walking_xyz_dynaslam_rgbd.txt");
  EXPECT_EQ(evaluation.ate.pairs.size(), 757u);
  EXPECT_NEAR(evaluation.ate.statistics.rmse, 0.016314, kMetreTolerance);
  EXPECT_NEAR(evaluation.ate.statistics.mean, 0.013869, kMetreTolerance);
  EXPECT_NEAR(evaluation.rpe.translational.rmse, 0.021809, kMetreTolerance);
  EXPECT_NEAR(evaluation.rpe.rotational_deg.rmse, 0.618397, kDegreeTolerance);
}

TEST(EvalReference, MatchesTheTumToolsWithOneFrameDelta) {
  SEGSLAM_REQUIRE_SHARED(dir, "reference_trajectories");
  TrajectoryEvaluationOptions options;
  options.rpe.delta_unit = DeltaUnit::kFrames;
  const auto evaluation = evaluateTrajectoryFiles(dir / "walking_xyz_groundtruth.txt",
                                                  dir / "walking_xyz_dynaslam_rgbd.txt", options);
  EXPECT_NEAR(evaluation.rpe.translational.rmse, 0.012535, kMetreTolerance);
  EXPECT_NEAR(evaluation.rpe.rotational_deg.rmse, 0.398473, kDegreeTolerance);
}

TEST(EvalFiles, UnreadableFileIsNamed) {
  const segslam::testing::ScopedTempDir temp;
  const auto gt = temp.path() / "gt.txt";
  io::writeTumTrajectory(gt, fixtures::wigglyPath(20));
  const auto missing = temp.path() / "missing.txt";
  try {
    evaluateTrajectoryFiles(gt, missing);
    FAIL() << "expected an error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
}

TEST(EvalFiles, TrajectoriesFromDifferentTimesNameBothFiles) {
  const segslam::testing::ScopedTempDir temp;
  const auto gt = temp.path() / "gt.txt";
  const auto est = temp.path() / "est.txt";
  io::writeTumTrajectory(gt, fixtures::wigglyPath(20));
  io::writeTumTrajectory(est, fixtures::alongX({5000, 5001, 5002}, {0, 1, 2}));
  try {
    evaluateTrajectoryFiles(gt, est);
    FAIL() << "expected an error";
  } catch (const util::Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(est.string() + ": ATE against " + gt.string(), 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace segslam::eval
