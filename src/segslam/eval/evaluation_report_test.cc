#include "segslam/eval/evaluation_report.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>

#include "segslam/eval/test_trajectories.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::eval {
namespace {

TrajectoryEvaluation smallEvaluation(AlignmentMethod alignment) {
  TrajectoryEvaluation evaluation;
  evaluation.ground_truth_file = "gt.txt";
  evaluation.estimate_file = "est.txt";
  evaluation.options.ate.alignment = alignment;
  evaluation.ground_truth = fixtures::wigglyPath(50);
  evaluation.estimate =
      fixtures::transformed(evaluation.ground_truth, fixtures::poseAt({0.02, 0.0, 0.0}, 2.0));
  evaluation.ate =
      evaluateAte(evaluation.ground_truth, evaluation.estimate, evaluation.options.ate);
  evaluation.rpe =
      evaluateRpe(evaluation.ground_truth, evaluation.estimate, evaluation.options.rpe);
  return evaluation;
}

TEST(EvalReport, TableHasOneLinePerMetric) {
  const auto table = formatEvaluationTable(smallEvaluation(AlignmentMethod::kSe3));
  EXPECT_NE(table.find("ground truth  gt.txt (50 poses)"), std::string::npos) << table;
  EXPECT_NE(table.find("ATE (SE3, 50 pairs)"), std::string::npos) << table;
  EXPECT_NE(table.find("RPE trans (delta 1 s, "), std::string::npos) << table;
  EXPECT_NE(table.find("RPE rot   (delta 1 s, "), std::string::npos) << table;
  EXPECT_NE(table.find(" deg"), std::string::npos) << table;
  EXPECT_EQ(table.find(" \n"), std::string::npos) << "trailing spaces";
  EXPECT_EQ(table.find("scale"), std::string::npos);
}

TEST(EvalReport, Sim3TableShowsTheScale) {
  const auto table = formatEvaluationTable(smallEvaluation(AlignmentMethod::kSim3));
  EXPECT_NE(table.find("ATE (Sim3, 50 pairs)"), std::string::npos) << table;
  EXPECT_NE(table.find("scale 1.000000"), std::string::npos) << table;
}

TEST(EvalReport, JsonHoldsOptionsCountsStatisticsAndAlignment) {
  const auto evaluation = smallEvaluation(AlignmentMethod::kSe3);
  const auto json = evaluationJson(evaluation);
  EXPECT_EQ(json["ground_truth"]["file"], "gt.txt");
  EXPECT_EQ(json["estimate"]["poses"], 50);
  EXPECT_EQ(json["options"]["ate"]["alignment"], "se3");
  EXPECT_EQ(json["options"]["rpe"]["delta_unit"], "s");
  EXPECT_EQ(json["ate"]["pairs"], 50);
  EXPECT_DOUBLE_EQ(json["ate"]["translational"]["rmse"].get<double>(),
                   evaluation.ate.statistics.rmse);
  EXPECT_EQ(json["ate"]["transform"].size(), 4u);
  EXPECT_DOUBLE_EQ(json["ate"]["transform"][3][3].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(json["ate"]["scale"].get<double>(), 1.0);
  EXPECT_EQ(json["rpe"]["pairs"], evaluation.rpe->pairs.size());
  EXPECT_FALSE(json.contains("rpe_not_computed"));
  EXPECT_EQ(json["rpe"]["rotational"]["unit"], "deg");
  for (const auto* key : {"count", "rmse", "mean", "median", "std", "min", "max"}) {
    EXPECT_TRUE(json["rpe"]["translational"].contains(key)) << key;
  }
}

TEST(EvalReport, AnRpeThatCannotBeComputedSaysWhy) {
  auto evaluation = smallEvaluation(AlignmentMethod::kSe3);
  evaluation.rpe.reset();
  evaluation.rpe_not_computed = "the estimate spans 0.6 s";
  const auto table = formatEvaluationTable(evaluation);
  EXPECT_NE(table.find("ATE (SE3, 50 pairs)"), std::string::npos) << table;
  EXPECT_NE(table.find(
                fmt::format("\n{:<36}not computed: the estimate spans 0.6 s\n", "RPE (delta 1 s)")),
            std::string::npos)
      << table;
  EXPECT_EQ(table.find("RPE trans"), std::string::npos) << table;
  const auto json = evaluationJson(evaluation);
  EXPECT_TRUE(json["rpe"].is_null());
  EXPECT_EQ(json["rpe_not_computed"], "the estimate spans 0.6 s");
  EXPECT_EQ(json["ate"]["pairs"], 50);
}

TEST(EvalReport, WritesJsonFiles) {
  const segslam::testing::ScopedTempDir temp;
  const auto file = temp.path() / "sub" / "results.json";
  writeEvaluationJson(file, smallEvaluation(AlignmentMethod::kSe3));
  std::ifstream in(file);
  EXPECT_EQ(nlohmann::json::parse(in)["ate"]["pairs"], 50);
  EXPECT_THROW(
      writeEvaluationJson("/proc/no/results.json", smallEvaluation(AlignmentMethod::kNone)),
      util::Error);
}

}  // namespace
}  // namespace segslam::eval
