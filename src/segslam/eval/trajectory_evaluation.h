#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "segslam/core/trajectory.h"
#include "segslam/eval/ate.h"
#include "segslam/eval/rpe.h"
#include "segslam/io/ground_truth_frame.h"

namespace segslam::eval {

struct TrajectoryEvaluationOptions {
  AteOptions ate;
  RpeOptions rpe;
};

// Both metrics for one estimate against its ground truth, with the inputs they came from. The ATE
// is always there; the RPE can be impossible where the ATE is not (an estimate shorter than the
// RPE's delta of 1 s has no pose pairs to compare).
struct TrajectoryEvaluation {
  std::filesystem::path ground_truth_file;
  // What the file holds poses of; `ground_truth` is always the camera's (io::toCameraPoses).
  io::GroundTruthFrame ground_truth_frame = io::GroundTruthFrame::kCamera;
  std::filesystem::path estimate_file;
  TrajectoryEvaluationOptions options;
  core::Trajectory ground_truth;
  core::Trajectory estimate;
  AteResult ate;
  std::optional<RpeResult> rpe;
  std::string rpe_not_computed;  // why, when there is no RPE
};

// The RPE of the evaluation, or the reason why it cannot be computed in rpe_not_computed.
void addRpe(TrajectoryEvaluation& evaluation);

// Reads two TUM trajectory files and computes ATE and RPE, the RPE only where it can be computed;
// the ground truth's poses are converted to the camera's from `ground_truth_frame` first.
// Every util::Error (unreadable file, too little overlap for the ATE) names the file it is about.
TrajectoryEvaluation evaluateTrajectoryFiles(
    const std::filesystem::path& ground_truth_file, const std::filesystem::path& estimate_file,
    const TrajectoryEvaluationOptions& options = {},
    io::GroundTruthFrame ground_truth_frame = io::GroundTruthFrame::kCamera);

}  // namespace segslam::eval
