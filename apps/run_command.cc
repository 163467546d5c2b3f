#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <limits>
#include <optional>

#include "commands.h"
#include "dataset_arguments.h"
#include "mask_arguments.h"
#include "occupancy_arguments.h"
#include "segslam/io/camera_config.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/place/vocabulary.h"
#include "segslam/system/loop_detector_choice.h"
#include "segslam/system/sequence_runner.h"
#include "segslam/util/logging.h"
#include "segslam/util/output_folder.h"
#include "segslam/util/progress.h"

namespace segslam::apps {

namespace {

// A verified loop whose relative pose is farther than this from the ground truth's is false.
constexpr double kFalseLoopTranslationM = 0.1;
constexpr double kFalseLoopRotationDeg = 5.0;

std::filesystem::path defaultVocabularyFile() {
  return std::filesystem::path(SEGSLAM_CONFIG_DIR) / place::kDefaultVocabularyFile;
}

struct RunOptions : DatasetArguments {
  std::size_t start_frame = 0;
  MaskArguments masks;
  system::SequenceRunOptions run;
  std::string loop_detector = "auto";
  std::filesystem::path vocabulary = defaultVocabularyFile();
  std::filesystem::path backbone_config =
      std::filesystem::path(SEGSLAM_CONFIG_DIR) / "models" / "tiny_darknet_imagenet.yaml";
  std::optional<std::filesystem::path> backbone_model;
};

// The loop detector asked for ("auto" resolved), its vocabulary and backbone loaded.
void configureLoopDetection(RunOptions& options) {
  const system::LoopDetectionRequest request{
      options.run.slam.loop_closing, options.loop_detector,   options.vocabulary,
      defaultVocabularyFile(),       options.backbone_config, options.backbone_model};
  const auto detection = system::configureLoopDetection(request, options.run.slam);
  options.run.map_file.place_recognition = detection.detector;
  options.run.map_file.vocabulary_file = detection.vocabulary_file;
}

void printEvaluation(const system::SequenceRunSummary& s) {
  if (!s.evaluation) {
    fmt::print("  ATE        not computed: {}\n", s.evaluation_not_computed);
    return;
  }
  const auto& ate = s.evaluation->ate.statistics;
  fmt::print("  ATE        rmse {:.4f} m (mean {:.4f}, median {:.4f}, max {:.4f}) over {} poses\n",
             ate.rmse, ate.mean, ate.median, ate.max, ate.count);
  if (s.tracked_ate_rmse_m) {
    fmt::print("             smoothed; as tracked {:.4f} m (CameraTrajectoryTracked.txt)\n",
               *s.tracked_ate_rmse_m);
  }
  if (s.ground_truth_frame != io::GroundTruthFrame::kCamera) {
    fmt::print("             ground truth: {}\n",
               io::describeGroundTruthFrame(s.ground_truth_frame));
  }
  if (const auto& rpe = s.evaluation->rpe) {
    fmt::print("  RPE (1 s)  {:.4f} m, {:.3f} deg rmse\n", rpe->translational.rmse,
               rpe->rotational_deg.rmse);
  } else {
    fmt::print("  RPE (1 s)  not computed: {}\n", s.evaluation->rpe_not_computed);
  }
}

void printSummary(const RunOptions& options, const system::SequenceRunSummary& s) {
  fmt::print("\nsegslam run: {} (masks: {})\n", options.dataset.string(), options.masks.source);
  fmt::print(
      "  frames     {} tracked of {} ({} lost, {} skipped for damaged images), {} keyframes, "
      "{} map points\n",
      s.tracked_frames, s.frames, s.lost_frames, s.skipped_frames, s.keyframes, s.map_points);
  if (s.absent_images > 0) {
    fmt::print(
        "  absent     {} listed images not in the dataset, their frames left out (the log "
        "names them)\n",
        s.absent_images);
  }
  fmt::print(
      "  tracking   median {:.1f} ms, p95 {:.1f} ms per frame (ORB extraction median {:.1f} ms)\n",
      s.tracking.median_ms, s.tracking.p95_ms, s.extraction.median_ms);
  fmt::print(
      "  speed      {:.1f} frames/s tracked ({:.1f} s from the first frame to the last), "
      "{:.1f} frames/s end to end ({:.1f} s wall, setup and finishing the map included)\n",
      s.tracking_frames_per_second, s.tracking_seconds, s.frames_per_second, s.wall_seconds);
  fmt::print("  resources  local BA {:.1f} s, peak RSS {} MB\n", s.bundle_adjustment_seconds,
             s.peak_rss_mb);
  if (s.realtime) {
    fmt::print(
        "  realtime   frames at the dataset's rate, taken up a median {:.1f} ms (p95 {:.1f}, "
        "max {:.1f}) after arrival\n",
        s.realtime_lag.median_ms, s.realtime_lag.p95_ms, s.realtime_lag.max_ms);
  }
  if (s.estimated_readout_s) {
    fmt::print(
        "  shutter    rolling, rows read in {:.1f} ms (estimated; the camera says {:.1f} ms)\n",
        *s.estimated_readout_s * 1e3, s.configured_readout_s * 1e3);
  }
  if (s.network_runs > 0) {
    const std::string where =
        options.run.slam.deterministic
            ? fmt::format("inline, every {} frames, used {} frames later",
                          options.masks.network_interval, options.masks.network_latency)
            : "own thread";
    fmt::print("  network    ran on {} of {} frames, {:.0f} ms each ({})\n", s.network_runs,
               s.frames, s.network_mean_ms, where);
    const auto& own = s.own_masks;
    fmt::print(
        "  keyframes  {} of {} mapped with their own network mask, {:.1f} frames after they were "
        "made (mean); {} of their points culled on moving objects\n",
        own.keyframes_with_own_mask, own.keyframes_with_own_mask + own.keyframes_without,
        own.mean_wait_frames, own.points_culled);
  }
  if (s.loop_closing) {
    int true_loops = 0;
    int false_loops = 0;
    for (const auto& check : s.loop_checks) {
      if (!check) continue;
      const bool agrees = check->translation_error_m < kFalseLoopTranslationM &&
                          check->rotation_error_deg < kFalseLoopRotationDeg;
      ++(agrees ? true_loops : false_loops);
    }
    fmt::print("  loops      {} accepted of {} verified candidates ({} detector)",
               s.loops.loops_accepted, s.loops.consistent_candidates, s.loops.detector);
    if (true_loops + false_loops > 0) {
      fmt::print(" ({} within {:.2f} m and {:.0f} deg of ground truth, {} not)", true_loops,
                 kFalseLoopTranslationM, kFalseLoopRotationDeg, false_loops);
    }
    fmt::print(", {} global BA\n", s.loops.global_bas_completed);
    if (s.loops.detector == "cnn" && s.loops.keyframes_described > 0) {
      fmt::print("  loop CNN   {:.1f} ms per keyframe on the loop-closing thread (wall)\n",
                 s.loops.describe_ms_total / s.loops.keyframes_described);
    }
  }
  printEvaluation(s);
  if (const auto& m = s.map_file) {
    if (!m->loaded_file.empty()) {
      fmt::print(
          "  map file   loaded {} ({} keyframes, {} points, {:.1f} MB in {:.2f} s) as session "
          "{}{}; "
          "first tracked frame {}; {} loaded points culled\n",
          m->loaded_file.string(), m->loaded_keyframes, m->loaded_points, m->loaded_bytes / 1e6,
          m->load_seconds, m->session, m->localize_only ? ", localisation only" : "",
          m->first_tracked_frame ? std::to_string(*m->first_tracked_frame) : "none",
          m->loaded_points_culled);
    }
    if (!m->saved_file.empty()) {
      fmt::print("  map file   saved {} ({:.1f} MB)\n", m->saved_file.string(),
                 m->saved_bytes / 1e6);
    }
  }
  if (s.map) {
    fmt::print(
        "  map        {} static and {} dynamic points, {} objects from {} keyframes "
        "({:.1f} s CPU for keyframe clouds, {:.1f} s to build)\n",
        s.map->static_points, s.map->dynamic_points, s.map->objects, s.map->keyframes,
        s.map->keyFrameSeconds(), s.map->build_seconds);
    if (s.map->occupancy) printOccupancySummary(*s.map->occupancy);
  }
  fmt::print("  outputs    {}\n", std::filesystem::absolute(options.out_dir).string());
}

void runCommand(RunOptions& options) {
  const auto dataset = openDataset(options).startingAt(options.start_frame);
  util::createOutputFolder(options.out_dir);  // before the networks load: fail early
  options.run.masks = maskSourceOptions(options.masks);
  configureLoopDetection(options);

  util::addLogFile(options.out_dir / "run.log");
  io::writeCameraYaml(options.out_dir / "camera.yaml", dataset.camera());
  spdlog::info("dataset {}: {} frames{}, camera {}, masks {}", options.dataset.string(),
               dataset.size(),
               options.start_frame > 0 ? fmt::format(" from frame {}", options.start_frame) : "",
               dataset.cameraSource(), options.masks.source);

  util::ProgressBar progress("tracking", std::min(options.run.max_frames, dataset.size()));
  const auto summary = system::runSequence(dataset, options.run, options.out_dir,
                                           [&](const system::FrameStats&) { progress.advance(); });
  progress.finish();
  printSummary(options, summary);
}

}  // namespace

void registerRunCommand(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  auto* run = app.add_subcommand("run", "Run SLAM on an RGB-D sequence in the TUM layout");
  addDatasetOptions(*run, *options);
  addMaskOptions(*run, options->masks);
  run->add_option("--mask-dilation", options->run.slam.mask_dilation_px,
                  "Dilation of the dynamic mask before feature extraction (pixels)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  run->add_option("--cull-seen-through", options->run.slam.tracker.seen_through_frames_to_cull,
                  "Cull map points that this many frames' depth sees through: they were on "
                  "something that moved away (0 = off)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  run->add_flag(
      "--no-late-mask-culling",
      [options](std::int64_t) { options->run.slam.tracker.late_mask_max_age = 0; },
      "Keep map points that a network output, arriving after its frame, shows on a "
      "moving object");
  run->add_option("--features", options->run.slam.orb.num_features, "ORB features per frame")
      ->capture_default_str()
      ->check(CLI::Range(100, 10000));
  run->add_flag("--no-loop-closing{false}", options->run.slam.loop_closing,
                "Do not detect and close loops (loop closing is on by default)");
  run->add_option(
         "--loop-consistency", options->run.slam.loop.consecutive_queries,
         "Consecutive keyframes that must propose the same place before a loop is verified")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  run->add_option("--keyframes-after-loop", options->run.slam.loop.keyframes_after_loop,
                  "Keyframes made after a loop correction before the next loop is sought")
      ->capture_default_str();
  run->add_option("--loop-detector", options->loop_detector,
                  "Loop candidates: auto (cnn when the backbone is found, else bow), bow (bag "
                  "of words of the static area, needs the vocabulary), vote (descriptor vote, no "
                  "vocabulary) or cnn (CNN descriptor with the union mask, needs the backbone)")
      ->check(CLI::IsMember(system::loopDetectorNames()))
      ->capture_default_str();
  run->add_option("--backbone-config", options->backbone_config,
                  "CNN backbone description (YAML) of the cnn loop detector")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  run->add_option("--backbone-model", options->backbone_model,
                  "CNN backbone file (ONNX) overriding the config's; else the config's path or "
                  "$SEGSLAM_MODEL_DIR");
  run->add_option("--cnn-layer", options->run.slam.loop_cnn.layer,
                  "Layer of the backbone config compared by the cnn loop detector")
      ->capture_default_str();
  run->add_option(
         "--vocabulary", options->vocabulary,
         "Bag-of-words vocabulary for relocalisation and the bow loop detector (segslam vocab "
         "train)")
      ->capture_default_str();
  run->add_flag("--deterministic", options->run.slam.deterministic,
                "Run local mapping inline after each keyframe: reproducible results, slower");
  auto* deterministic = run->get_option("--deterministic");
  // A dataset plays at its camera's rate by default, as ORB-SLAM2's TUM example plays it: played
  // as fast as frames load, tracking outruns local mapping and the network (bench/playback.sh).
  options->run.realtime = true;
  auto* realtime = run->add_flag("--realtime", options->run.realtime,
                                 "Hand frames over at the dataset's frame rate, as a camera would "
                                 "(the default)")
                       ->excludes(deterministic);
  run->add_flag(
         "--fast", [options](std::int64_t) { options->run.realtime = false; },
         "Hand frames over as fast as they load: the throughput of tracking (local mapping and "
         "the network fall behind, so the ATE is worse)")
      ->excludes(deterministic)
      ->excludes(realtime);
  run->add_flag(
      "--no-smoothing", [options](std::int64_t) { options->run.slam.trajectory_smoothing.reset(); },
      "Write the camera trajectory as tracked, not smoothed under a camera moving at "
      "near-constant velocity (smoothed runs also write CameraTrajectoryTracked.txt)");
  run->add_option("--seed", options->run.seed, "Seed of the random number generators")
      ->capture_default_str();
  run->add_option("--start-frame", options->start_frame,
                  "Start at this frame of the sequence (0 = the first), as a camera switched on "
                  "then: the frames before are not played")
      ->capture_default_str();
  run->add_option("--max-frames", options->run.max_frames, "Process at most this many frames")
      ->check(CLI::PositiveNumber);
  run->add_flag("--map,!--no-map", options->run.build_map,
                "Build the dense map of the keyframes into map/ (default on)");
  run->add_option("--map-voxel", options->run.map.keyframe.voxel_size,
                  "Voxel size of the dense map (metres)")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 1.0));
  addOccupancyOptions(*run, options->run.occupancy);
  run->add_option("--map-outlier-neighbours", options->run.map.cleaning.outlier_neighbours,
                  "Neighbours of the map's statistical outlier removal (0: no removal)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  auto* load_map =
      run->add_option("--load-map", options->run.map_file.load,
                      "Start in the map saved by an earlier run (--save-map): the first frames are "
                      "relocalised into it wherever the camera is, and the run extends it");
  run->add_option("--save-map", options->run.map_file.save,
                  "At the end, write the SLAM map (keyframes, points, covisibility) to this file "
                  "for --load-map (docs/map_file.md)");
  run->add_flag("--localize-only", options->run.map_file.localize_only,
                "With --load-map: track against the loaded map without adding keyframes or points "
                "or changing it")
      ->needs(load_map);
  run->add_option("--localise-within", options->run.map_file.frames_to_localise,
                  "With --load-map: stop with an error when no frame was localised in the loaded "
                  "map within this many frames")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  run->callback([options] {
    if (options->run.slam.deterministic) options->run.realtime = false;
    if (options->out_dir.empty()) options->out_dir = defaultOutDir(options->dataset, "run");
    runCommand(*options);
  });
}

}  // namespace segslam::apps
