#pragma once

#include <filesystem>
#include <vector>

#include "segslam/eval/trajectory_evaluation.h"

namespace segslam::eval {

// Writes the evaluation plots into `folder` (created if needed; util::Error naming it when it
// cannot be) and returns the files written:
//   trajectory_top.svg  aligned estimate and ground truth seen along the ground truth's flattest
//                       axis (the two axes it extends most along are drawn, equal scale)
//   trajectory_xyz.svg  x, y and z of both over time
//   ate_error.svg       ATE per matched pose over time
//   rpe_error.svg       RPE translational and rotational error per pair over time (only with an
//                       RPE)
// Times are seconds since the first ground-truth pose.
std::vector<std::filesystem::path> writeEvaluationPlots(const std::filesystem::path& folder,
                                                        const TrajectoryEvaluation& evaluation);

}  // namespace segslam::eval
