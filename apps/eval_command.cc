#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "dataset_arguments.h"
#include "segslam/eval/evaluation_plots.h"
#include "segslam/eval/evaluation_report.h"
#include "segslam/eval/trajectory_evaluation.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/util/output_folder.h"

namespace segslam::apps {

namespace {

struct TrajectoryEvalSettings {
  std::string ground_truth;
  std::string estimate;
  double max_difference = 0.02;
  double offset = 0.0;
  double scale = 1.0;
  std::string alignment = "se3";
  double rpe_delta = 1.0;
  std::string rpe_unit = "s";
  bool rpe_any_pairs = false;
  std::size_t rpe_max_pairs = 10000;
  std::uint64_t rpe_seed = 0;
  std::string plots;
  std::optional<std::string> json;  // present: JSON wanted; empty: on stdout
  std::string aligned_out;
  std::string ground_truth_frame = "auto";
};

// As --gt-frame says; by default the marker poses of a groundtruth.txt in a Bonn sequence's
// folder, as published, and camera poses for any other file.
io::GroundTruthFrame groundTruthFrame(const TrajectoryEvalSettings& s) {
  if (const auto frame = io::parseGroundTruthFrame(s.ground_truth_frame)) return *frame;
  const std::filesystem::path file = std::filesystem::absolute(s.ground_truth);
  if (file.filename() != "groundtruth.txt") return io::GroundTruthFrame::kCamera;
  return io::groundTruthFrameForDataset(file.parent_path());
}

eval::TrajectoryEvaluationOptions evaluationOptions(const TrajectoryEvalSettings& s) {
  eval::TrajectoryEvaluationOptions options;
  options.ate = {s.max_difference, s.offset, s.scale, *eval::parseAlignmentMethod(s.alignment)};
  options.rpe.fixed_delta = !s.rpe_any_pairs;
  options.rpe.delta = s.rpe_delta;
  options.rpe.delta_unit = *eval::parseDeltaUnit(s.rpe_unit);
  options.rpe.max_pairs = s.rpe_max_pairs;
  options.rpe.offset = s.offset;
  options.rpe.scale = s.scale;
  options.rpe.seed = s.rpe_seed;
  return options;
}

// Before evaluating: a bad output path fails at once rather than after the table is printed.
void createOutputFolders(const TrajectoryEvalSettings& s) {
  if (!s.plots.empty()) util::createOutputFolder(s.plots);
  if (s.json && !s.json->empty()) util::createFolderFor(*s.json);
  if (!s.aligned_out.empty()) util::createFolderFor(s.aligned_out);
}

void evaluateTrajectory(const TrajectoryEvalSettings& s) {
  createOutputFolders(s);
  const auto evaluation = eval::evaluateTrajectoryFiles(s.ground_truth, s.estimate,
                                                        evaluationOptions(s), groundTruthFrame(s));
  const bool json_on_stdout = s.json && s.json->empty();
  // JSON on stdout replaces the table, so the output stays parseable.
  if (json_on_stdout) {
    std::cout << eval::evaluationJson(evaluation).dump(2) << '\n';
  } else {
    fmt::print("{}", eval::formatEvaluationTable(evaluation));
  }
  if (s.json && !s.json->empty()) {
    eval::writeEvaluationJson(*s.json, evaluation);
    spdlog::info("wrote {}", *s.json);
  }
  if (!s.plots.empty()) {
    eval::writeEvaluationPlots(s.plots, evaluation);
    spdlog::info("wrote plots to {}", s.plots);
  }
  if (!s.aligned_out.empty()) {
    io::writeTumTrajectory(
        s.aligned_out, evaluation.ate.aligned_estimate,
        fmt::format("{} aligned onto {} ({})", s.estimate, s.ground_truth, s.alignment));
    spdlog::info("wrote {}", s.aligned_out);
  }
}

void addTrajectoryOptions(CLI::App& command, TrajectoryEvalSettings& s) {
  command.add_option("--gt", s.ground_truth, "Ground-truth trajectory, TUM format")
      ->type_name("FILE");
  command.add_option("--est", s.estimate, "Estimated trajectory, TUM format")->type_name("FILE");
  addGroundTruthFrameOption(command, s.ground_truth_frame);
  command.add_option("--max-diff", s.max_difference, "ATE: largest time difference to match [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--offset", s.offset, "Time offset added to the estimate's stamps [s]")
      ->capture_default_str();
  command.add_option("--scale", s.scale, "Scale applied to the estimate's translations")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--align", s.alignment, "ATE alignment of the estimate")
      ->check(CLI::IsMember(eval::alignmentMethodNames()))
      ->capture_default_str();
  command.add_option("--rpe-delta", s.rpe_delta, "RPE: distance between compared poses")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command
      .add_option("--rpe-unit", s.rpe_unit, "RPE: unit of --rpe-delta (s, f = frames, m, deg, rad)")
      ->check(CLI::IsMember(eval::deltaUnitNames()))
      ->capture_default_str();
  command.add_flag("--rpe-any-pairs", s.rpe_any_pairs,
                   "RPE: compare all pose pairs (random ones beyond --rpe-max-pairs) instead of "
                   "pairs --rpe-delta apart, like the TUM tool without --fixed_delta");
  command
      .add_option("--rpe-max-pairs", s.rpe_max_pairs,
                  "RPE: most pairs compared, randomly chosen beyond it; 0 = no limit")
      ->capture_default_str();
  command
      .add_option("--rpe-seed", s.rpe_seed,
                  "RPE: seed for choosing random pairs (the TUM tool's choice is unseeded)")
      ->capture_default_str();
  command.add_option("--plots", s.plots, "Write trajectory and error plots (SVG) into this folder")
      ->type_name("DIR");
  command
      .add_option("--json", s.json,
                  "Write the results as JSON to FILE, or to stdout (instead of the table) when "
                  "no FILE is given")
      ->type_name("[FILE]")
      ->expected(0, 1);
  command
      .add_option("--aligned-out", s.aligned_out,
                  "Write the aligned estimate as a TUM trajectory file")
      ->type_name("FILE");
}

}  // namespace

void registerEvalCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "eval",
      "Evaluate an estimated trajectory against ground truth: ATE and RPE computed as the TUM "
      "RGB-D benchmark tools (evaluate_ate.py, evaluate_rpe.py --fixed_delta) do");
  command->footer(
      "Example: segslam eval --gt groundtruth.txt --est estimate.txt --plots plots/ --json "
      "results.json\nWith no sub-command, `eval` evaluates the trajectory given by --gt and "
      "--est; further evaluations are added as sub-commands of `eval`.");
  command->require_subcommand(0, 1);
  registerEvalMasksCommand(*command);
  registerEvalLoopsCommand(*command);
  registerEvalMapCommand(*command);
  auto settings = std::make_shared<TrajectoryEvalSettings>();
  addTrajectoryOptions(*command, *settings);
  command->callback([command, settings] {
    // --gt and --est are checked here rather than marked required, so that sub-commands of
    // `eval` do not need them.
    if (!command->get_subcommands().empty()) return;
    if (settings->ground_truth.empty()) throw CLI::RequiredError("--gt");
    if (settings->estimate.empty()) throw CLI::RequiredError("--est");
    evaluateTrajectory(*settings);
  });
}

}  // namespace segslam::apps
