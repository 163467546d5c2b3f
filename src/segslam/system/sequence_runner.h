#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "segslam/eval/trajectory_evaluation.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/system/map_output.h"
#include "segslam/system/map_persistence.h"
#include "segslam/system/mask_source.h"
#include "segslam/system/occupancy_output.h"
#include "segslam/system/slam_pipeline.h"

namespace segslam::system {

// The pipeline's options (SLAM, dense map, map files) and the run's.
struct SequenceRunOptions : SlamPipelineOptions {
  MaskSourceOptions masks;
  std::size_t max_frames = std::numeric_limits<std::size_t>::max();
  eval::TrajectoryEvaluationOptions evaluation;
  std::uint64_t seed = 0;
  // The occupancy map built with the dense map (map/occupancy.bt, the floor grid); with
  // map_file.load it carries on the loaded session's.
  OccupancyOutputOptions occupancy;
  // Frames are handed to SLAM no earlier than a camera would deliver them (the dataset's
  // timestamps, from the first frame on) instead of as fast as they load: the timing a robot
  // sees, where the segmentation network has the frame interval to keep up.
  bool realtime = false;
};

struct TimingSummary {
  double median_ms = 0.0;
  double p95_ms = 0.0;
  double mean_ms = 0.0;
  double max_ms = 0.0;
};

// What a run did with map files.
struct MapFileSummary {
  std::filesystem::path loaded_file;  // empty: the run started a new map
  std::uintmax_t loaded_bytes = 0;
  double load_seconds = 0.0;
  std::size_t loaded_keyframes = 0;
  std::size_t loaded_points = 0;
  // Loaded points gone at the end: seen through, on a moving object, or merged and culled by
  // local mapping.
  std::size_t loaded_points_culled = 0;
  std::uint32_t session = 0;
  bool localize_only = false;
  // The first frame tracked (localised in the loaded map, or starting the new one).
  std::optional<std::size_t> first_tracked_frame;
  std::filesystem::path saved_file;  // empty: not saved
  std::uintmax_t saved_bytes = 0;
};

struct SequenceRunSummary {
  std::size_t frames = 0;  // played, skipped ones included
  std::size_t tracked_frames = 0;
  std::size_t lost_frames = 0;
  std::size_t skipped_frames = 0;  // for a damaged image: never handed to masks or SLAM
  // Listed colour and depth images the dataset lacks (io::TumDataset::absentImages): the frames
  // they belong to are not among `frames`.
  std::size_t absent_images = 0;
  std::size_t keyframes = 0;
  std::size_t map_points = 0;
  TimingSummary tracking;  // per frame, extraction included
  TimingSummary extraction;
  double wall_seconds = 0.0;       // frame loading included
  double frames_per_second = 0.0;  // end to end
  // From the first frame taken to the last frame tracked: what tracking sustains, without the
  // setup before (loading networks) and the mapping, loop closing and global BA it leaves to
  // finish after the last frame.
  double tracking_seconds = 0.0;
  double tracking_frames_per_second = 0.0;
  // Realtime playback: how far the processing of a frame started after the frame's arrival.
  bool realtime = false;
  TimingSummary realtime_lag;
  double bundle_adjustment_seconds = 0.0;
  long peak_rss_mb = 0;
  int network_runs = 0;  // semantic masks: frames the network actually ran on
  double network_mean_ms = 0.0;
  int points_culled_by_late_masks = 0;
  mapping::OwnMaskStats own_masks;
  // The camera's rolling-shutter readout and tracking's estimate of it (s); empty for a global
  // shutter.
  double configured_readout_s = 0.0;
  std::optional<double> estimated_readout_s;
  // The ATE, and the RPE where it can be computed (evaluation->rpe_not_computed says why not), of
  // the written trajectory: smoothed unless SlamOptions::trajectory_smoothing is none.
  std::optional<eval::TrajectoryEvaluation> evaluation;
  bool trajectory_smoothed = false;
  std::optional<double> tracked_ate_rmse_m;  // of the tracked poses, when smoothed
  bool has_ground_truth = false;
  io::GroundTruthFrame ground_truth_frame = io::GroundTruthFrame::kCamera;
  std::string evaluation_not_computed;  // why there is no evaluation
  std::optional<MapSummary> map;
  std::optional<MapFileSummary> map_file;
  bool loop_closing = false;
  loop::LoopClosingStats loops;
  // Per accepted loop with ground truth: how far its verified relative pose is from the true one
  // (a false loop shows as an error of decimetres or more).
  struct LoopCheck {
    double translation_error_m = 0.0;
    double rotation_error_deg = 0.0;
  };
  std::vector<std::optional<LoopCheck>> loop_checks;
  std::vector<std::filesystem::path> outputs;
};

// Runs SLAM over a dataset and writes the run folder: CameraTrajectory.txt and
// KeyFrameTrajectory.txt (TUM format), frame_log.csv (per-frame timings and state),
// summary.json, with ground truth evaluation.json and the evaluation plots (where the ATE can be
// computed: an evaluation that cannot be is reported in the summary and does not fail the run),
// and with build_map the dense map (map/static.ply, map/dynamic.ply, map/objects.json,
// map/objects/*.ply) built from the keyframes' images and final poses, labelled by the network
// (semantic, fused masks: see FrameMaskSource::masks) or else by the dataset's labels and
// instances when it has them.
// Frames with a damaged image (io::DamagedImageError) are skipped with a warning and counted;
// throws util::Error when more than half of them are (io::DamagedFrames), and when the dataset
// lacks what the options need (e.g. oracle masks). With map_file.load the run starts in the saved
// map (a bad or foreign file, or a camera not localised in it within
// map_file.frames_to_localise frames, throws util::Error naming the file); with map_file.save
// the final map is written there. The run's dense map folder (out_dir/map) replaces
// options.dense_map_folder.
SequenceRunSummary runSequence(const io::TumDataset& dataset, const SequenceRunOptions& options,
                               const std::filesystem::path& out_dir,
                               const std::function<void(const FrameStats&)>& on_frame);

nlohmann::json toJson(const SequenceRunSummary& summary);

}  // namespace segslam::system
