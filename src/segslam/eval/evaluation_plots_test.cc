#include "segslam/eval/evaluation_plots.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "segslam/eval/test_trajectories.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

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

TEST(EvalPlots, WithoutRpeThereIsNoRpePlot) {
  const segslam::testing::ScopedTempDir temp;
  auto evaluation = evaluationInTheXzPlane();
  evaluation.rpe.reset();
  evaluation.rpe_not_computed = "too short";
  const auto files = writeEvaluationPlots(temp.path(), evaluation);
  EXPECT_EQ(files, (std::vector<std::filesystem::path>{temp.path() / "trajectory_top.svg",
                                                       temp.path() / "trajectory_xyz.svg",
                                                       temp.path() / "ate_error.svg"}));
  EXPECT_FALSE(std::filesystem::exists(temp.path() / "rpe_error.svg"));
}

TEST(EvalPlots, AFolderThatCannotBeCreatedIsNamed) {
  const segslam::testing::ScopedTempDir temp;
  const auto file = temp.path() / "file.txt";
  std::ofstream(file) << "x";
  try {
    writeEvaluationPlots(file / "plots", evaluationInTheXzPlane());
    FAIL() << "expected an error";
  } catch (const util::Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot create output folder " + (file / "plots").string() + ": Not a directory");
  }
}

}  // namespace
}  // namespace segslam::eval
