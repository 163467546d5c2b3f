#include "segslam/system/sequence_runner.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <opencv2/core/utility.hpp>
#include <optional>

#include "segslam/eval/closest_index.h"
#include "segslam/eval/evaluation_plots.h"
#include "segslam/eval/evaluation_report.h"
#include "segslam/io/damaged_frames.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/system/frame_log.h"
#include "segslam/system/frame_player.h"
#include "segslam/system/map_session_layers.h"
#include "segslam/util/elapsed_time.h"
#include "segslam/util/error.h"

namespace segslam::system {

namespace {

TimingSummary summarise(std::vector<double> values) {
  TimingSummary summary;
  if (values.empty()) return summary;
  std::sort(values.begin(), values.end());
  const auto at = [&](double q) {
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
  };
  summary.median_ms = at(0.5);
  summary.p95_ms = at(0.95);
  double sum = 0.0;
  for (double v : values) sum += v;
  summary.mean_ms = sum / static_cast<double>(values.size());
  summary.max_ms = values.back();
  return summary;
}

long peakRssMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;
}

nlohmann::json timingJson(const TimingSummary& t) {
  return {{"median_ms", t.median_ms},
          {"p95_ms", t.p95_ms},
          {"mean_ms", t.mean_ms},
          {"max_ms", t.max_ms}};
}

// The ATE, and the RPE where it can be computed. What cannot be computed is reported with its
// reason, never fails the run: a run of a few frames is shorter than the RPE's delta of 1 s.
void evaluate(const io::TumDataset& dataset, const SequenceRunOptions& options,
              const std::filesystem::path& out_dir, const core::Trajectory& estimate,
              const core::Trajectory& tracked, SequenceRunSummary& summary) {
  summary.has_ground_truth = dataset.groundTruth().has_value();
  summary.ground_truth_frame = dataset.groundTruthFrame();
  if (!summary.has_ground_truth) {
    summary.evaluation_not_computed = "the dataset has no groundtruth.txt";
    return;
  }
  eval::TrajectoryEvaluation evaluation;
  evaluation.ground_truth_file = dataset.folder() / "groundtruth.txt";
  evaluation.ground_truth_frame = dataset.groundTruthFrame();
  evaluation.estimate_file = out_dir / "CameraTrajectory.txt";
  evaluation.options = options.evaluation;
  evaluation.ground_truth = *dataset.groundTruth();
  evaluation.estimate = estimate;
  try {
    evaluation.ate = eval::evaluateAte(evaluation.ground_truth, estimate, options.evaluation.ate);
  } catch (const util::Error& e) {
    summary.evaluation_not_computed = e.what();
    spdlog::warn("no trajectory evaluation: {}", e.what());
    return;
  }
  if (summary.trajectory_smoothed) {
    summary.tracked_ate_rmse_m =
        eval::evaluateAte(evaluation.ground_truth, tracked, options.evaluation.ate).statistics.rmse;
  }
  eval::addRpe(evaluation);
  if (!evaluation.rpe) spdlog::warn("RPE not computed: {}", evaluation.rpe_not_computed);
  eval::writeEvaluationJson(out_dir / "evaluation.json", evaluation);
  io::writeTumTrajectory(out_dir / "GroundTruthAligned.txt",
                         eval::groundTruthInEstimateFrame(evaluation.ground_truth, evaluation.ate,
                                                          options.evaluation.ate),
                         "ground truth in the estimate's frame (inverse of the ATE alignment)");
  summary.outputs.push_back(out_dir / "evaluation.json");
  summary.outputs.push_back(out_dir / "GroundTruthAligned.txt");
  for (auto& plot : eval::writeEvaluationPlots(out_dir / "plots", evaluation)) {
    summary.outputs.push_back(plot);
  }
  summary.evaluation = std::move(evaluation);
}

void writeSummaryJson(const std::filesystem::path& file, const SequenceRunSummary& summary) {
  std::ofstream out(file);
  out << toJson(summary).dump(2) << "\n";
  if (!out) util::failAt(file, "cannot write");
}

std::optional<geometry::Pose> groundTruthNear(const core::Trajectory& ground_truth, double t) {
  if (ground_truth.empty()) return std::nullopt;
  const auto timestamps = ground_truth.timestamps();
  const std::size_t i = eval::findClosestIndex(timestamps, t);
  if (std::abs(timestamps[i] - t) > 0.02) return std::nullopt;
  return ground_truth[i].T_wc;
}

void checkLoops(const io::TumDataset& dataset, SequenceRunSummary& summary) {
  for (const loop::LoopRecord& record : summary.loops.loops) {
    std::optional<SequenceRunSummary::LoopCheck> check;
    if (dataset.groundTruth()) {
      const auto query = groundTruthNear(*dataset.groundTruth(), record.query_timestamp);
      const auto loop = groundTruthNear(*dataset.groundTruth(), record.loop_timestamp);
      if (query && loop) {
        // T_query_loop = T_query_w * T_w_loop from the ground truth's camera-to-world poses.
        const geometry::Pose truth = query->inverse() * *loop;
        const geometry::Pose error = record.T_query_loop.inverse() * truth;
        check = SequenceRunSummary::LoopCheck{error.translation().norm(),
                                              geometry::rotationAngle(error) * 180.0 / M_PI};
      }
    }
    summary.loop_checks.push_back(check);
  }
}

void describeLoadedMap(const std::filesystem::path& file, const LoadedMap& loaded,
                       const SlamSystem& slam, MapFileSummary& summary) {
  summary.loaded_file = file;
  summary.loaded_bytes = loaded.file_bytes;
  summary.load_seconds = loaded.load_seconds;
  summary.loaded_keyframes = loaded.contents.keyframes.size();
  summary.loaded_points = loaded.contents.points.size();
  summary.session = slam.sessions().current;
  spdlog::info("map {}: {} keyframes, {} points, session {}, loaded in {:.3f} s", file.string(),
               summary.loaded_keyframes, summary.loaded_points, summary.session,
               summary.load_seconds);
}

// A loaded map that the camera does not find itself in soon is the wrong map (or the wrong
// place): the run stops rather than track nothing. A sequence shorter than the deadline must be
// localised by its last frame.
void checkLocalised(const MapFileOptions& options, std::size_t frame_index, std::size_t frames,
                    const FrameStats& stats, MapFileSummary& summary) {
  if (!summary.first_tracked_frame && stats.state == tracking::TrackingState::kOk) {
    summary.first_tracked_frame = frame_index;
    if (options.load) spdlog::info("frame {}: localised in the loaded map", frame_index);
  }
  const std::size_t deadline = std::min(options.frames_to_localise, frames);
  if (options.load && !summary.first_tracked_frame && frame_index + 1 >= deadline) {
    util::failAt(*options.load,
                 fmt::format("the camera was not localised in this map within its first {} frames "
                             "(another place, or another map?)",
                             deadline));
  }
}

// Saves the map and, for the viewer, its layer per session into the run folder.
void finishMapFile(const MapFileOptions& options, SlamPipeline& pipeline,
                   const std::filesystem::path& out_dir, MapFileSummary& summary) {
  summary.localize_only = options.localize_only;
  if (pipeline.loadedMap()) {
    summary.loaded_points_culled = summary.loaded_points - pipeline.slam().restoredPointsLeft();
  }
  if (!options.save) return;
  summary.saved_file = *options.save;
  summary.saved_bytes = pipeline.saveMap(*options.save);
  spdlog::info("map saved to {} ({} bytes)", options.save->string(), summary.saved_bytes);
  writeSessionLayers(map::readMapFile(*options.save), out_dir / "map_sessions");
}

nlohmann::json mapFileJson(const MapFileSummary& m) {
  nlohmann::json json = {{"session", m.session}, {"localize_only", m.localize_only}};
  json["first_tracked_frame"] =
      m.first_tracked_frame ? nlohmann::json(*m.first_tracked_frame) : nlohmann::json(nullptr);
  if (!m.loaded_file.empty()) {
    json["loaded_file"] = m.loaded_file.string();
    json["loaded_bytes"] = m.loaded_bytes;
    json["load_seconds"] = m.load_seconds;
    json["loaded_keyframes"] = m.loaded_keyframes;
    json["loaded_points"] = m.loaded_points;
    json["loaded_points_culled"] = m.loaded_points_culled;
  }
  if (!m.saved_file.empty()) {
    json["saved_file"] = m.saved_file.string();
    json["saved_bytes"] = m.saved_bytes;
  }
  return json;
}

// The run's occupancy options; with a loaded map, its session's occupancy map carries on.
OccupancyOutputOptions occupancyOptions(const SequenceRunOptions& options,
                                        const std::optional<LoadedMap>& loaded) {
  OccupancyOutputOptions occupancy = options.occupancy;
  if (loaded) occupancy.earlier = linkedOccupancyMap(*loaded, *options.map_file.load);
  return occupancy;
}

SlamPipelineOptions pipelineOptions(const SequenceRunOptions& options,
                                    const std::filesystem::path& out_dir) {
  SlamPipelineOptions pipeline = options;
  pipeline.dense_map_folder = options.build_map ? out_dir / "map" : "";
  return pipeline;
}

}  // namespace

SequenceRunSummary runSequence(const io::TumDataset& dataset, const SequenceRunOptions& options,
                               const std::filesystem::path& out_dir,
                               const std::function<void(const FrameStats&)>& on_frame) {
  cv::setRNGSeed(static_cast<int>(options.seed));
  std::filesystem::create_directories(out_dir);
  const auto start = std::chrono::steady_clock::now();
  SequenceRunSummary summary;
  summary.frames = std::min(options.max_frames, dataset.size());
  summary.absent_images = dataset.absentImages().size();
  FrameLog frame_log(out_dir / "frame_log.csv");
  std::vector<double> realtime_lag_ms;
  {
    auto mask_options = options.masks;
    mask_options.carry_labels = options.build_map;  // only the object map reads labels
    FrameMaskSource masks(dataset, mask_options, options.slam.deterministic);
    SlamPipeline pipeline(dataset.camera(), masks, pipelineOptions(options, out_dir));
    const SlamSystem& slam = pipeline.slam();
    if (options.map_file.load || options.map_file.save) summary.map_file.emplace();
    if (const auto& loaded = pipeline.loadedMap()) {
      describeLoadedMap(*options.map_file.load, *loaded, slam, *summary.map_file);
    }
    // Ground-truth masks feed oracle masks only; labels and instances only the object map.
    const io::FrameLayers layers{options.masks.source == MaskSource::kOracle, options.build_map,
                                 options.build_map};
    FramePlayer player(dataset, masks, {layers, options.realtime, !options.slam.deterministic});
    const auto first_frame = std::chrono::steady_clock::now();
    io::DamagedFrames damaged(dataset.folder(), summary.frames);
    for (std::size_t i = 0; i < summary.frames; ++i) {
      const PlayedFrame played = player.take(i, summary.frames - 1);
      if (played.damage) {
        damaged.skip(i, dataset.frames()[i].timestamp, *played.damage);
        continue;
      }
      if (options.realtime) realtime_lag_ms.push_back(played.lag_ms);
      const FrameStats stats =
          pipeline.track(played.frame, played.masks, played.frame_id, played.mask_ms);
      frame_log.add(stats);
      if (on_frame) on_frame(stats);
      if (summary.map_file) {
        checkLocalised(options.map_file, i, summary.frames, stats, *summary.map_file);
      }
    }
    summary.skipped_frames = damaged.count();
    summary.tracking_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - first_frame).count();
    pipeline.finish();
    summary.network_runs = masks.networkRuns();
    summary.network_mean_ms = masks.meanNetworkMilliseconds();
    summary.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto trajectory = slam.cameraTrajectory();
    const auto tracked = slam.trackedCameraTrajectory();
    summary.trajectory_smoothed = options.slam.trajectory_smoothing.has_value();
    io::writeTumTrajectory(out_dir / "CameraTrajectory.txt", trajectory,
                           summary.trajectory_smoothed ? "segslam camera trajectory, smoothed"
                                                       : "segslam camera trajectory");
    io::writeTumTrajectory(out_dir / "KeyFrameTrajectory.txt", slam.keyFrameTrajectory(),
                           "segslam keyframe trajectory");
    summary.outputs = {out_dir / "CameraTrajectory.txt", out_dir / "KeyFrameTrajectory.txt"};
    if (summary.trajectory_smoothed) {
      io::writeTumTrajectory(out_dir / "CameraTrajectoryTracked.txt", tracked,
                             "segslam camera trajectory as tracked, before smoothing");
      summary.outputs.push_back(out_dir / "CameraTrajectoryTracked.txt");
    }
    if (dense::MapBuilder* map_builder = pipeline.mapBuilder()) {
      summary.map = buildAndWriteMap(*map_builder, slam.keyFrameTrajectory(), out_dir / "map",
                                     occupancyOptions(options, pipeline.loadedMap()));
      summary.outputs.push_back(out_dir / "map");
    }
    if (summary.map_file) finishMapFile(options.map_file, pipeline, out_dir, *summary.map_file);
    summary.points_culled_by_late_masks = pipeline.pointsCulledByLateMasks();
    summary.tracked_frames = trajectory.size();
    summary.keyframes = slam.numKeyFrames();
    summary.map_points = slam.numMapPoints();
    summary.bundle_adjustment_seconds = slam.bundleAdjustmentSeconds();
    summary.loop_closing = options.slam.loop_closing && !options.map_file.localize_only;
    summary.loops = slam.loopClosingStats();
    summary.own_masks = slam.ownMaskStats();
    summary.configured_readout_s = dataset.camera().rolling_shutter_readout_s;
    summary.estimated_readout_s = slam.rollingShutterReadout();
    checkLoops(dataset, summary);
    evaluate(dataset, options, out_dir, trajectory, tracked, summary);
  }
  summary.lost_frames = frame_log.lostFrames();
  summary.tracking = summarise(frame_log.trackingMs());
  summary.extraction = summarise(frame_log.extractionMs());
  summary.realtime = options.realtime;
  summary.realtime_lag = summarise(realtime_lag_ms);
  summary.frames_per_second = summary.frames / std::max(summary.wall_seconds, 1e-9);
  summary.tracking_frames_per_second = summary.frames / std::max(summary.tracking_seconds, 1e-9);
  summary.peak_rss_mb = peakRssMegabytes();
  frame_log.close();
  summary.outputs.push_back(out_dir / "frame_log.csv");
  writeSummaryJson(out_dir / "summary.json", summary);
  summary.outputs.push_back(out_dir / "summary.json");
  return summary;
}

namespace {

nlohmann::json loopClosingJson(const SequenceRunSummary& summary) {
  const loop::LoopClosingStats& stats = summary.loops;
  nlohmann::json loops = nlohmann::json::array();
  for (std::size_t i = 0; i < stats.loops.size(); ++i) {
    const loop::LoopRecord& record = stats.loops[i];
    nlohmann::json entry = {{"query_keyframe", record.query_keyframe},
                            {"loop_keyframe", record.loop_keyframe},
                            {"query_timestamp", record.query_timestamp},
                            {"loop_timestamp", record.loop_timestamp},
                            {"inliers", record.inliers},
                            {"correction_m", record.drift_m}};
    if (i < summary.loop_checks.size() && summary.loop_checks[i]) {
      entry["ground_truth_translation_error_m"] = summary.loop_checks[i]->translation_error_m;
      entry["ground_truth_rotation_error_deg"] = summary.loop_checks[i]->rotation_error_deg;
    }
    loops.push_back(entry);
  }
  return {
      {"detector", stats.detector},
      {"candidates_verified", stats.consistent_candidates},
      {"loops_accepted", stats.loops_accepted},
      {"global_bas_completed", stats.global_bas_completed},
      {"global_bas_cancelled", stats.global_bas_cancelled},
      {"describe_ms_mean",
       stats.keyframes_described > 0 ? stats.describe_ms_total / stats.keyframes_described : 0.0},
      {"loops", loops}};
}

void addRpeJson(const std::optional<eval::RpeResult>& rpe, const std::string& not_computed,
                nlohmann::json& json) {
  json["rpe_translational_rmse_m"] = rpe ? nlohmann::json(rpe->translational.rmse) : nullptr;
  json["rpe_rotational_rmse_deg"] = rpe ? nlohmann::json(rpe->rotational_deg.rmse) : nullptr;
  if (!rpe) json["rpe_not_computed"] = not_computed;
}

// Without ground truth the figures are left out; with it, a figure that could not be computed is
// null with its reason beside it.
void addEvaluationJson(const SequenceRunSummary& summary, nlohmann::json& json) {
  if (summary.has_ground_truth) {
    json["ground_truth"] = {{"frame", io::groundTruthFrameName(summary.ground_truth_frame)},
                            {"poses_of", io::describeGroundTruthFrame(summary.ground_truth_frame)}};
  }
  json["trajectory_smoothed"] = summary.trajectory_smoothed;
  if (const auto& evaluation = summary.evaluation) {
    json["ate_rmse_m"] = evaluation->ate.statistics.rmse;
    if (summary.tracked_ate_rmse_m) json["ate_tracked_rmse_m"] = *summary.tracked_ate_rmse_m;
    addRpeJson(evaluation->rpe, evaluation->rpe_not_computed, json);
  } else if (summary.has_ground_truth) {
    json["ate_rmse_m"] = nullptr;
    json["ate_not_computed"] = summary.evaluation_not_computed;
    addRpeJson(std::nullopt, summary.evaluation_not_computed, json);
  }
}

}  // namespace

nlohmann::json toJson(const SequenceRunSummary& summary) {
  nlohmann::json json = {{"frames", summary.frames},
                         {"tracked_frames", summary.tracked_frames},
                         {"lost_frames", summary.lost_frames},
                         {"skipped_frames", summary.skipped_frames},
                         {"absent_images", summary.absent_images},
                         {"keyframes", summary.keyframes},
                         {"map_points", summary.map_points},
                         {"tracking_time", timingJson(summary.tracking)},
                         {"extraction_time", timingJson(summary.extraction)},
                         {"wall_seconds", summary.wall_seconds},
                         {"frames_per_second", summary.frames_per_second},
                         {"tracking_seconds", summary.tracking_seconds},
                         {"tracking_frames_per_second", summary.tracking_frames_per_second},
                         {"bundle_adjustment_seconds", summary.bundle_adjustment_seconds},
                         {"peak_rss_mb", summary.peak_rss_mb}};
  if (summary.realtime) json["realtime_lag"] = timingJson(summary.realtime_lag);
  if (summary.estimated_readout_s) {
    json["rolling_shutter_readout_s"] = {{"configured", summary.configured_readout_s},
                                         {"estimated", *summary.estimated_readout_s}};
  }
  if (summary.loop_closing) json["loop_closing"] = loopClosingJson(summary);
  if (summary.network_runs > 0) {
    json["network_runs"] = summary.network_runs;
    json["network_mean_ms"] = summary.network_mean_ms;
    json["points_culled_by_late_masks"] = summary.points_culled_by_late_masks;
    const mapping::OwnMaskStats& own = summary.own_masks;
    json["keyframe_own_masks"] = {{"keyframes_with_own_mask", own.keyframes_with_own_mask},
                                  {"keyframes_without", own.keyframes_without},
                                  {"mean_wait_frames", own.mean_wait_frames},
                                  {"points_culled", own.points_culled},
                                  {"observations_dropped", own.observations_dropped}};
  }
  if (summary.map) json["map"] = toJson(*summary.map);
  if (summary.map_file) json["map_file"] = mapFileJson(*summary.map_file);
  addEvaluationJson(summary, json);
  return json;
}

}  // namespace segslam::system
