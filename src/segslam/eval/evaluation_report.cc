#include "segslam/eval/evaluation_report.h"

#include <fmt/format.h>
#include <fmt/os.h>

#include <system_error>

#include "segslam/util/error.h"
#include "segslam/util/output_folder.h"

namespace segslam::eval {

namespace {

constexpr int kLabelWidth = 36;

std::string alignmentTitle(AlignmentMethod method) {
  switch (method) {
    case AlignmentMethod::kSe3:
      return "SE3";
    case AlignmentMethod::kSim3:
      return "Sim3";
    case AlignmentMethod::kNone:
      return "unaligned";
  }
  return "";
}

std::string rpePairingTitle(const RpeOptions& options) {
  if (options.fixed_delta) {
    return fmt::format("delta {:g} {}", options.delta, deltaUnitName(options.delta_unit));
  }
  return "any pairs";
}

std::string statisticsLine(const std::string& label, const ErrorStatistics& stats,
                           std::string_view unit) {
  // Units are padded so that the columns of metre and degree lines line up.
  const auto figure = [&](std::string_view name, double value) {
    return fmt::format("{} {:.6f} {:<5}", name, value, unit);
  };
  std::string line =
      fmt::format("{:<{}}{}{}{}{}{}{}", label, kLabelWidth, figure("rmse", stats.rmse),
                  figure("mean", stats.mean), figure("median", stats.median),
                  figure("std", stats.std), figure("min", stats.min), figure("max", stats.max));
  line.erase(line.find_last_not_of(' ') + 1);
  return line + '\n';
}

nlohmann::json statisticsJson(const ErrorStatistics& stats, std::string_view unit) {
  return {{"count", stats.count},   {"rmse", stats.rmse}, {"mean", stats.mean},
          {"median", stats.median}, {"std", stats.std},   {"min", stats.min},
          {"max", stats.max},       {"unit", unit}};
}

nlohmann::json matrixJson(const Eigen::Matrix4d& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  return rows;
}

nlohmann::json optionsJson(const TrajectoryEvaluationOptions& options) {
  return {{"ate",
           {{"max_difference", options.ate.max_difference},
            {"offset", options.ate.offset},
            {"scale", options.ate.scale},
            {"alignment", alignmentMethodName(options.ate.alignment)}}},
          {"rpe",
           {{"fixed_delta", options.rpe.fixed_delta},
            {"delta", options.rpe.delta},
            {"delta_unit", deltaUnitName(options.rpe.delta_unit)},
            {"max_pairs", options.rpe.max_pairs},
            {"offset", options.rpe.offset},
            {"scale", options.rpe.scale},
            {"seed", options.rpe.seed}}}};
}

// Says so where the file's poses were converted to the camera's.
std::string groundTruthNote(const TrajectoryEvaluation& evaluation) {
  if (evaluation.ground_truth_frame == io::GroundTruthFrame::kCamera) return "";
  return "; " + io::describeGroundTruthFrame(evaluation.ground_truth_frame);
}

}  // namespace

std::string formatEvaluationTable(const TrajectoryEvaluation& evaluation) {
  const auto& ate = evaluation.ate;
  const auto& rpe = evaluation.rpe;
  std::string table =
      fmt::format("{:<14}{} ({} poses{})\n{:<14}{} ({} poses)\n", "ground truth",
                  evaluation.ground_truth_file.string(), evaluation.ground_truth.size(),
                  groundTruthNote(evaluation), "estimate", evaluation.estimate_file.string(),
                  evaluation.estimate.size());
  const std::string ate_label = fmt::format(
      "ATE ({}, {} pairs)", alignmentTitle(evaluation.options.ate.alignment), ate.pairs.size());
  table += statisticsLine(ate_label, ate.statistics, "m");
  if (evaluation.options.ate.alignment == AlignmentMethod::kSim3) {
    table += fmt::format("{:<{}}scale {:.6f}\n", "", kLabelWidth, ate.alignment.scale);
  }
  if (!rpe) {
    const std::string label = fmt::format("RPE ({})", rpePairingTitle(evaluation.options.rpe));
    return table +
           fmt::format("{:<{}}not computed: {}\n", label, kLabelWidth, evaluation.rpe_not_computed);
  }
  const std::string rpe_title =
      fmt::format("{}, {} pairs", rpePairingTitle(evaluation.options.rpe), rpe->pairs.size());
  table += statisticsLine(fmt::format("RPE trans ({})", rpe_title), rpe->translational, "m");
  table += statisticsLine(fmt::format("RPE rot   ({})", rpe_title), rpe->rotational_deg, "deg");
  return table;
}

nlohmann::json evaluationJson(const TrajectoryEvaluation& evaluation) {
  const auto& ate = evaluation.ate;
  nlohmann::json json = {
      {"ground_truth",
       {{"file", evaluation.ground_truth_file.string()},
        {"poses", evaluation.ground_truth.size()},
        {"frame", io::groundTruthFrameName(evaluation.ground_truth_frame)},
        {"poses_of", io::describeGroundTruthFrame(evaluation.ground_truth_frame)}}},
      {"estimate",
       {{"file", evaluation.estimate_file.string()}, {"poses", evaluation.estimate.size()}}},
      {"options", optionsJson(evaluation.options)},
      {"ate",
       {{"pairs", ate.pairs.size()},
        {"alignment", alignmentMethodName(evaluation.options.ate.alignment)},
        {"transform", matrixJson(ate.alignment.matrix())},
        {"scale", ate.alignment.scale},
        {"translational", statisticsJson(ate.statistics, "m")}}},
  };
  if (const auto& rpe = evaluation.rpe) {
    json["rpe"] = {{"pairs", rpe->pairs.size()},
                   {"translational", statisticsJson(rpe->translational, "m")},
                   {"rotational", statisticsJson(rpe->rotational_deg, "deg")}};
  } else {
    json["rpe"] = nullptr;
    json["rpe_not_computed"] = evaluation.rpe_not_computed;
  }
  return json;
}

void writeEvaluationJson(const std::filesystem::path& file,
                         const TrajectoryEvaluation& evaluation) {
  util::createFolderFor(file);
  try {
    auto out = fmt::output_file(file.string());
    out.print("{}\n", evaluationJson(evaluation).dump(2));
  } catch (const std::system_error& e) {
    util::failAt(file, fmt::format("cannot write: {}", e.what()));
  }
}

}  // namespace segslam::eval
