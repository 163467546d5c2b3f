#include "segslam/eval/evaluation_plots.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "segslam/eval/test_trajectories.h"
#include "segslam/testing/test_support.h"

namespace segslam::eval {
namespace {

// A ground truth that moves in x and z only, so the top view must show x and z.
TrajectoryEvaluation evaluationInTheXzPlane() {
  TrajectoryEvaluation evaluation;
  for (int k = 0; k < 40; ++k) {
    const double t = 0.1 * k;
    evaluation.ground_truth.append(t, fixtures::poseAt({std::cos(t), 0.01 * t, std::sin(t)}));
  }
  evaluation.estimate =
      fixtures::transformed(evaluation.ground_truth, fixtures::poseAt({0.0, 0.03, 0.0}, 1.0));
  evaluation.ate = evaluateAte(evaluation.ground_truth, evaluation.estimate);
  evaluation.rpe = evaluateRpe(evaluation.ground_truth, evaluation.estimate);
  return evaluation;
}

TEST(EvalPlots, WritesFourSvgFiles) {
  const segslam::testing::ScopedTempDir temp;
  const auto folder = temp.path() / "plots";
  const auto files = writeEvaluationPlots(folder, evaluationInTheXzPlane());
  ASSERT_EQ(files.size(), 4u);
  for (const auto* name :
       {"trajectory_top.svg", "trajectory_xyz.svg", "ate_error.svg", "rpe_error.svg"}) {
    const auto svg = segslam::testing::fileContents(folder / name);
    EXPECT_EQ(svg.rfind("<svg", 0), 0u) << name;
    EXPECT_NE(svg.find("<polyline"), std::string::npos) << name;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << name;
  }
}

TEST(EvalPlots, TopViewShowsTheTwoWidestAxes) {
  const segslam::testing::ScopedTempDir temp;
  writeEvaluationPlots(temp.path(), evaluationInTheXzPlane());
  const auto top = segslam::testing::fileContents(temp.path() / "trajectory_top.svg");
  EXPECT_NE(top.find(">x [m]</text>"), std::string::npos);
  EXPECT_NE(top.find(">z [m]</text>"), std::string::npos);
  EXPECT_EQ(top.find(">y [m]</text>"), std::string::npos);
  const auto xyz = segslam::testing::fileContents(temp.path() / "trajectory_xyz.svg");
  EXPECT_NE(xyz.find(">y [m]</text>"), std::string::npos);
  EXPECT_NE(xyz.find("estimate (SE3-aligned)"), std::string::npos);
}

}  // namespace
}  // namespace segslam::eval
