#pragma once

#include <filesystem>

#include "segslam/core/trajectory.h"
#include "segslam/eval/ate.h"
#include "segslam/eval/rpe.h"

namespace segslam::eval {

struct TrajectoryEvaluationOptions {
  AteOptions ate;
  RpeOptions rpe;
};

// Both metrics for one estimate against its ground truth, with the inputs they came from.
struct TrajectoryEvaluation {
  std::filesystem::path ground_truth_file;
  std::filesystem::path estimate_file;
  TrajectoryEvaluationOptions options;
  core::Trajectory ground_truth;
  core::Trajectory estimate;
  AteResult ate;
  RpeResult rpe;
};

// Reads two TUM trajectory files and computes ATE and RPE. Every util::Error (unreadable file,
// too little overlap) names the file it is about.
TrajectoryEvaluation evaluateTrajectoryFiles(const std::filesystem::path& ground_truth_file,
                                             const std::filesystem::path& estimate_file,
                                             const TrajectoryEvaluationOptions& options = {});

}  // namespace segslam::eval
