#include "segslam/eval/trajectory_evaluation.h"

#include <fmt/format.h>

#include "segslam/io/trajectory_io.h"
#include "segslam/util/error.h"

namespace segslam::eval {

namespace {

// The metrics know nothing of files; failures about the pair are reported on the estimate, which
// is the file a user most likely got wrong, naming the ground truth too.
template <typename Evaluate>
auto reportingFiles(const TrajectoryEvaluation& evaluation, std::string_view metric,
                    Evaluate evaluate) {
  try {
    return evaluate();
  } catch (const util::Error& e) {
    util::failAt(
        evaluation.estimate_file,
        fmt::format("{} against {}: {}", metric, evaluation.ground_truth_file.string(), e.what()));
  }
}

}  // namespace

TrajectoryEvaluation evaluateTrajectoryFiles(const std::filesystem::path& ground_truth_file,
                                             const std::filesystem::path& estimate_file,
                                             const TrajectoryEvaluationOptions& options,
                                             io::GroundTruthFrame ground_truth_frame) {
  TrajectoryEvaluation evaluation;
  evaluation.ground_truth_file = ground_truth_file;
  evaluation.ground_truth_frame = ground_truth_frame;
  evaluation.estimate_file = estimate_file;
  evaluation.options = options;
  evaluation.ground_truth =
      io::toCameraPoses(io::readTumTrajectory(ground_truth_file), ground_truth_frame);
  evaluation.estimate = io::readTumTrajectory(estimate_file);
  evaluation.ate = reportingFiles(evaluation, "ATE", [&] {
    return evaluateAte(evaluation.ground_truth, evaluation.estimate, options.ate);
  });
  addRpe(evaluation);
  return evaluation;
}

void addRpe(TrajectoryEvaluation& evaluation) {
  try {
    evaluation.rpe =
        evaluateRpe(evaluation.ground_truth, evaluation.estimate, evaluation.options.rpe);
    evaluation.rpe_not_computed.clear();
  } catch (const util::Error& e) {
    evaluation.rpe.reset();
    evaluation.rpe_not_computed = e.what();
  }
}

}  // namespace segslam::eval
