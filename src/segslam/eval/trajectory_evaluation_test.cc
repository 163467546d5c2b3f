#include "segslam/eval/trajectory_evaluation.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>

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
  ASSERT_TRUE(evaluation.rpe) << evaluation.rpe_not_computed;
  EXPECT_NEAR(evaluation.rpe->translational.rmse, 0.021809, kMetreTolerance);
  EXPECT_NEAR(evaluation.rpe->rotational_deg.rmse, 0.618397, kDegreeTolerance);
}

TEST(EvalReference, MatchesTheTumToolsWithOneFrameDelta) {
  SEGSLAM_REQUIRE_SHARED(dir, "reference_trajectories");
  TrajectoryEvaluationOptions options;
  options.rpe.delta_unit = DeltaUnit::kFrames;
  const auto evaluation = evaluateTrajectoryFiles(dir / "walking_xyz_groundtruth.txt",
                                                  dir / "walking_xyz_dynaslam_rgbd.txt", options);
  ASSERT_TRUE(evaluation.rpe) << evaluation.rpe_not_computed;
  EXPECT_NEAR(evaluation.rpe->translational.rmse, 0.012535, kMetreTolerance);
  EXPECT_NEAR(evaluation.rpe->rotational_deg.rmse, 0.398473, kDegreeTolerance);
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

// The text of `trajectory` as the TUM benchmark's files sometimes are: lines out of order, and
// timestamps repeated by earlier lines with other poses (the later line is the one that counts).
std::string shuffledWithEarlierDuplicates(const core::Trajectory& trajectory) {
  std::string text = "# timestamp tx ty tz qx qy qz qw\n";
  for (const std::size_t k : {5u, 50u, 120u}) {
    text += fmt::format("{:.6f} 9 9 9 0 0 0 1\n", trajectory[k].timestamp);
  }
  for (std::size_t k = trajectory.size(); k-- > 0;) {
    const Eigen::Vector3d t = trajectory[k].T_wc.translation();
    const Eigen::Quaterniond q(trajectory[k].T_wc.linear());
    text += fmt::format("{:.6f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f}\n",
                        trajectory[k].timestamp, t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
  }
  return text;
}

TEST(EvalFiles, DuplicatedAndUnorderedGroundTruthGivesTheFiguresOfTheCleanFile) {
  const segslam::testing::ScopedTempDir temp;
  const auto ground_truth = fixtures::wigglyPath(200);
  const auto clean = temp.path() / "clean.txt";
  const auto messy = temp.path() / "messy.txt";
  const auto est = temp.path() / "est.txt";
  io::writeTumTrajectory(clean, ground_truth);
  std::ofstream(messy) << shuffledWithEarlierDuplicates(ground_truth);
  io::writeTumTrajectory(est,
                         fixtures::transformed(ground_truth, fixtures::poseAt({0.1, 0, 0}, 3.0)));
  const auto expected = evaluateTrajectoryFiles(clean, est);
  const auto evaluation = evaluateTrajectoryFiles(messy, est);
  ASSERT_EQ(evaluation.ground_truth.size(), 200u);
  EXPECT_EQ(evaluation.ate.pairs.size(), expected.ate.pairs.size());
  EXPECT_EQ(evaluation.ate.statistics.rmse, expected.ate.statistics.rmse);
  EXPECT_EQ(evaluation.ate.statistics.max, expected.ate.statistics.max);
  ASSERT_TRUE(evaluation.rpe && expected.rpe);
  EXPECT_EQ(evaluation.rpe->pairs.size(), expected.rpe->pairs.size());
  EXPECT_EQ(evaluation.rpe->translational.rmse, expected.rpe->translational.rmse);
  EXPECT_EQ(evaluation.rpe->rotational_deg.rmse, expected.rpe->rotational_deg.rmse);
}

TEST(EvalFiles, AnEstimateTooShortForTheRpeStillHasItsAte) {
  const segslam::testing::ScopedTempDir temp;
  const auto gt = temp.path() / "gt.txt";
  const auto est = temp.path() / "est.txt";
  io::writeTumTrajectory(gt, fixtures::wigglyPath(50));
  io::writeTumTrajectory(est, fixtures::wigglyPath(6));  // the first 0.5 s of the ground truth
  const auto evaluation = evaluateTrajectoryFiles(gt, est);
  EXPECT_EQ(evaluation.ate.pairs.size(), 6u);
  EXPECT_LT(evaluation.ate.statistics.rmse, 1e-6);
  EXPECT_FALSE(evaluation.rpe);
  EXPECT_EQ(evaluation.rpe_not_computed,
            "the estimate spans 0.500 s (6 poses) and has 0 pose pair(s) 1 s apart (pairs ending "
            "at its last pose do not count, as in the TUM tool); need at least 2");
}

}  // namespace
}  // namespace segslam::eval
