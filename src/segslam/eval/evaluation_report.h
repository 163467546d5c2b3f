#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "segslam/eval/trajectory_evaluation.h"

namespace segslam::eval {

// Human-readable summary, one line per metric, e.g.
//   ATE (SE3, 757 pairs)              rmse 0.016314 m    mean 0.013869 m    median ...
// An RPE that could not be computed is one line saying why: "RPE (delta 1 s)  not computed: ...".
std::string formatEvaluationTable(const TrajectoryEvaluation& evaluation);

// The same figures for machines: input files, options, pair counts, all statistics and the
// alignment (4x4 similarity and its scale); without an RPE, "rpe": null and "rpe_not_computed":
// the reason.
nlohmann::json evaluationJson(const TrajectoryEvaluation& evaluation);

// Writes evaluationJson() indented to a file; throws util::Error naming it when that fails.
void writeEvaluationJson(const std::filesystem::path& file, const TrajectoryEvaluation& evaluation);

}  // namespace segslam::eval
