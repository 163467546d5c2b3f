#include "segslam/eval/evaluation_plots.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "segslam/eval/svg_plot.h"
#include "segslam/util/output_folder.h"

namespace segslam::eval {

namespace {

constexpr std::array<const char*, 3> kAxisNames{"x", "y", "z"};
constexpr const char* kGroundTruthColour = "#222222";
constexpr const char* kEstimateColour = "#1f77b4";
constexpr const char* kErrorColour = "#d62728";
constexpr const char* kRmseColour = "#ff7f0e";
constexpr const char* kTimeLabel = "time since first ground-truth pose [s]";

std::vector<double> coordinate(const core::Trajectory& trajectory, int axis) {
  std::vector<double> values;
  for (const auto& pose : trajectory.poses()) values.push_back(pose.T_wc.translation()[axis]);
  return values;
}

// Estimate stamps are shifted by the offset so both trajectories share the ground truth's clock.
std::vector<double> relativeTimes(const core::Trajectory& trajectory, double shift, double start) {
  std::vector<double> times;
  for (const auto& pose : trajectory.poses()) times.push_back(pose.timestamp + shift - start);
  return times;
}

// The two world axes along which the ground truth extends most, in axis order.
std::array<int, 2> widestAxes(const core::Trajectory& ground_truth) {
  std::array<double, 3> extent{};
  for (int axis = 0; axis < 3; ++axis) {
    const auto values = coordinate(ground_truth, axis);
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    extent[axis] = *high - *low;
  }
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return extent[a] > extent[b]; });
  return {std::min(order[0], order[1]), std::max(order[0], order[1])};
}

std::string estimateLabel(const TrajectoryEvaluation& evaluation) {
  switch (evaluation.options.ate.alignment) {
    case AlignmentMethod::kSe3:
      return "estimate (SE3-aligned)";
    case AlignmentMethod::kSim3:
      return "estimate (Sim3-aligned)";
    case AlignmentMethod::kNone:
      return "estimate";
  }
  return "estimate";
}

Plot topView(const TrajectoryEvaluation& evaluation) {
  const auto [h, v] = widestAxes(evaluation.ground_truth);
  Plot plot{.title = "Trajectory, top view",
            .x_label = fmt::format("{} [m]", kAxisNames[h]),
            .y_label = fmt::format("{} [m]", kAxisNames[v]),
            .equal_aspect = true};
  plot.series.push_back({"ground truth", coordinate(evaluation.ground_truth, h),
                         coordinate(evaluation.ground_truth, v), kGroundTruthColour});
  plot.series.push_back({estimateLabel(evaluation), coordinate(evaluation.ate.aligned_estimate, h),
                         coordinate(evaluation.ate.aligned_estimate, v), kEstimateColour});
  return plot;
}

std::vector<Plot> perAxis(const TrajectoryEvaluation& evaluation) {
  const double start = evaluation.ground_truth[0].timestamp;
  const auto gt_times = relativeTimes(evaluation.ground_truth, 0.0, start);
  const auto est_times =
      relativeTimes(evaluation.ate.aligned_estimate, evaluation.options.ate.offset, start);
  std::vector<Plot> plots;
  for (int axis = 0; axis < 3; ++axis) {
    Plot plot{.title = fmt::format("Trajectory, {} over time", kAxisNames[axis]),
              .x_label = kTimeLabel,
              .y_label = fmt::format("{} [m]", kAxisNames[axis])};
    plot.series.push_back(
        {"ground truth", gt_times, coordinate(evaluation.ground_truth, axis), kGroundTruthColour});
    plot.series.push_back({estimateLabel(evaluation), est_times,
                           coordinate(evaluation.ate.aligned_estimate, axis), kEstimateColour});
    plots.push_back(std::move(plot));
  }
  return plots;
}

// A dashed horizontal line at the RMSE across the whole time range of `times`.
PlotSeries rmseLine(const std::vector<double>& times, double rmse, std::string_view unit) {
  const auto [first, last] = std::minmax_element(times.begin(), times.end());
  return {fmt::format("RMSE {:.4f} {}", rmse, unit),
          {*first, *last},
          {rmse, rmse},
          kRmseColour,
          false,
          "6,4"};
}

Plot ateErrorPlot(const TrajectoryEvaluation& evaluation) {
  const double start = evaluation.ground_truth[0].timestamp;
  std::vector<double> times;
  std::vector<double> errors;
  for (const auto& pair : evaluation.ate.pairs) {
    times.push_back(pair.gt_stamp - start);
    errors.push_back(pair.error);
  }
  Plot plot{
      .title = fmt::format("Absolute trajectory error ({} pairs)", evaluation.ate.pairs.size()),
      .x_label = kTimeLabel,
      .y_label = "ATE [m]"};
  plot.series.push_back({"ATE", times, errors, kErrorColour});
  plot.series.push_back(rmseLine(times, evaluation.ate.statistics.rmse, "m"));
  return plot;
}

// Only for an evaluation with an RPE.
std::vector<Plot> rpeErrorPlots(const TrajectoryEvaluation& evaluation) {
  const double start = evaluation.ground_truth[0].timestamp;
  const RpeResult& rpe = *evaluation.rpe;
  std::vector<double> times;
  std::vector<double> translational;
  std::vector<double> rotational;
  for (const auto& pair : rpe.pairs) {
    times.push_back(pair.gt_stamp_0 - start);
    translational.push_back(pair.translational_error);
    rotational.push_back(pair.rotational_error_deg);
  }
  const auto& options = evaluation.options.rpe;
  // Pairs of any length have no meaningful order in time: draw them as dots.
  const bool markers = !options.fixed_delta;
  const std::string pairing = options.fixed_delta ? fmt::format("delta {:g} {}", options.delta,
                                                                deltaUnitName(options.delta_unit))
                                                  : std::string("any pairs");
  const std::string time_label = "time of the pair's first pose [s]";
  Plot trans{.title = fmt::format("Relative pose error, translation ({}, {} pairs)", pairing,
                                  rpe.pairs.size()),
             .x_label = time_label,
             .y_label = "RPE translation [m]"};
  trans.series.push_back({"RPE translation", times, translational, kErrorColour, markers});
  trans.series.push_back(rmseLine(times, rpe.translational.rmse, "m"));
  Plot rot{.title = fmt::format("Relative pose error, rotation ({}, {} pairs)", pairing,
                                rpe.pairs.size()),
           .x_label = time_label,
           .y_label = "RPE rotation [deg]"};
  rot.series.push_back({"RPE rotation", times, rotational, kErrorColour, markers});
  rot.series.push_back(rmseLine(times, rpe.rotational_deg.rmse, "deg"));
  return {trans, rot};
}

}  // namespace

std::vector<std::filesystem::path> writeEvaluationPlots(const std::filesystem::path& folder,
                                                        const TrajectoryEvaluation& evaluation) {
  util::createOutputFolder(folder);
  const std::vector<Plot> top{topView(evaluation)};
  const std::vector<Plot> ate{ateErrorPlot(evaluation)};
  std::vector<std::filesystem::path> files{folder / "trajectory_top.svg",
                                           folder / "trajectory_xyz.svg", folder / "ate_error.svg"};
  writeSvg(files[0], top, {860.0, 640.0});
  writeSvg(files[1], perAxis(evaluation), {860.0, 300.0});
  writeSvg(files[2], ate);
  if (evaluation.rpe) {
    files.push_back(folder / "rpe_error.svg");
    writeSvg(files[3], rpeErrorPlots(evaluation), {860.0, 320.0});
  }
  return files;
}

}  // namespace segslam::eval
