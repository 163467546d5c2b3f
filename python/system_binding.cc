#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <mutex>

#include "default_settings.h"
#include "frame_arrays.h"
#include "module_parts.h"
#include "numpy_arrays.h"
#include "segslam/place/vocabulary.h"
#include "segslam/system/loop_detector_choice.h"
#include "segslam/system/streaming_slam.h"
#include "segslam/util/elapsed_time.h"

namespace segslam::python {

namespace {

// The System's keyword arguments: `segslam run`'s options of the same names.
struct SystemSettings {
  std::string seg;
  std::string loop_detector;
  bool deterministic = false;
  bool loop_closing = true;
  int features = 0;
  int mask_dilation = 0;
  bool build_map = true;
  std::uint64_t seed = 0;
  std::filesystem::path model_config;
  std::optional<std::filesystem::path> model;
  std::optional<std::filesystem::path> vocabulary;
  std::filesystem::path backbone_config;
  std::optional<std::filesystem::path> backbone_model;
  int network_interval = 0;
  int network_latency = 0;
  std::string camera_motion;
  std::optional<std::filesystem::path> load_map;
  bool localize_only = false;
};

void requireRange(int value, int low, int high, std::string_view name) {
  if (value < low || value > high) {
    throw py::value_error(fmt::format("{} must be in [{}, {}], not {}", name, low, high, value));
  }
}

void checkRanges(const SystemSettings& settings) {
  requireRange(settings.features, 100, 10000, "features");
  requireRange(settings.mask_dilation, 0, 1000, "mask_dilation");
  requireRange(settings.network_interval, 1, 1000, "network_interval");
  requireRange(settings.network_latency, 0, 60, "network_latency");
}

// As `segslam run --seg`: "auto" is fused when the network is found, else geometric.
system::MaskSourceOptions maskOptions(const SystemSettings& settings) {
  system::MaskSourceOptions options;
  options.model_config = settings.model_config;
  options.model_file = settings.model;
  options.source = settings.seg == "auto" ? system::automaticMaskSource(options).source
                                          : system::maskSourceFromName(settings.seg);
  options.network_interval = settings.network_interval;
  options.network_latency = settings.network_latency;
  options.geometric.motion_model = segmentation::cameraMotionModelFromName(settings.camera_motion);
  return options;
}

// As `segslam run --loop-detector` and --vocabulary (system::configureLoopDetection); the
// resolved detector and vocabulary are the identity of a map this System saves.
std::string configureLoopDetection(const SystemSettings& settings,
                                   system::StreamingSlamOptions& options) {
  const auto& names = system::loopDetectorNames();
  if (std::find(names.begin(), names.end(), settings.loop_detector) == names.end()) {
    throw py::value_error(fmt::format("unknown loop_detector '{}' (known: {})",
                                      settings.loop_detector, fmt::join(names, ", ")));
  }
  const auto shipped = configDir() / place::kDefaultVocabularyFile;
  const system::LoopDetectionRequest request{settings.loop_closing,
                                             settings.loop_detector,
                                             settings.vocabulary.value_or(shipped),
                                             shipped,
                                             settings.backbone_config,
                                             settings.backbone_model};
  const auto detection = system::configureLoopDetection(request, options.slam);
  options.map_file.place_recognition = detection.detector;
  options.map_file.vocabulary_file = detection.vocabulary_file;
  return detection.detector;
}

// What one call of System.track gives back.
struct TrackResult {
  std::uint64_t frame_id = 0;
  double timestamp = 0.0;
  tracking::TrackingState state = tracking::TrackingState::kNotInitialised;
  py::object pose = py::none();
  py::object mask = py::none();
  py::object labels = py::none();
  bool keyframe = false;
  int keypoints = 0;
  int matches = 0;
  double tracking_ms = 0.0;
  double mask_ms = 0.0;
  double pipeline_ms = 0.0;
};

TrackResult toTrackResult(const system::StreamedFrame& streamed) {
  const system::FrameStats& stats = streamed.stats;
  TrackResult result{stats.frame_id, stats.timestamp, stats.state};
  if (stats.T_wc) result.pose = poseToNumpy(*stats.T_wc);
  if (!streamed.masks.dynamic.empty()) result.mask = toNumpy(streamed.masks.dynamic);
  if (!streamed.masks.labels.empty()) result.labels = toNumpy(streamed.masks.labels);
  result.keyframe = stats.keyframe;
  result.keypoints = stats.keypoints;
  result.matches = stats.matches;
  result.tracking_ms = stats.tracking_ms;
  result.mask_ms = stats.mask_ms;
  return result;
}

// The pipeline of `segslam run` for frames handed over one at a time. Calls from several
// threads take turns; none holds the GIL while the C++ works.
class System {
 public:
  System(const core::Camera& camera, const SystemSettings& settings) : camera_(camera) {
    checkRanges(settings);
    system::StreamingSlamOptions options;
    options.masks = maskOptions(settings);
    mask_source_ = system::maskSourceName(options.masks.source);
    options.slam.deterministic = settings.deterministic;
    options.slam.loop_closing = settings.loop_closing;
    options.slam.orb.num_features = settings.features;
    options.slam.mask_dilation_px = settings.mask_dilation;
    loop_detector_ = configureLoopDetection(settings, options);
    options.build_map = settings.build_map;
    options.seed = settings.seed;
    options.map_file.load = settings.load_map;
    options.map_file.localize_only = settings.localize_only;
    slam_ = std::make_unique<system::StreamingSlam>(camera, options);
  }

  TrackResult track(double timestamp, const py::array& rgb, const py::array& depth,
                    const py::object& mask) {
    if (!std::isfinite(timestamp)) throw py::value_error("timestamp must be finite");
    const FrameViews views = checkFrame(rgb, depth, mask, camera_);
    system::StreamedFrame streamed;
    double pipeline_ms = 0.0;
    {
      const py::gil_scoped_release unlocked;
      io::RgbdFrame frame = toRgbdFrame(timestamp, views, camera_);
      const std::lock_guard lock(mutex_);
      if (last_timestamp_ && !(timestamp > *last_timestamp_)) {
        throw py::value_error(fmt::format("timestamps must increase: {:.6f} after {:.6f}",
                                          timestamp, *last_timestamp_));
      }
      const auto start = std::chrono::steady_clock::now();
      streamed = slam_->track(frame);
      pipeline_ms = util::millisecondsSince(start);
      last_timestamp_ = timestamp;
    }
    TrackResult result = toTrackResult(streamed);
    result.pipeline_ms = pipeline_ms;
    return result;
  }

  void finish() {
    const py::gil_scoped_release unlocked;
    const std::lock_guard lock(mutex_);
    slam_->finish();
  }

  core::Trajectory trajectory() {
    const py::gil_scoped_release unlocked;
    const std::lock_guard lock(mutex_);
    return slam_->cameraTrajectory();
  }

  core::Trajectory trackedTrajectory() {
    const py::gil_scoped_release unlocked;
    const std::lock_guard lock(mutex_);
    return slam_->trackedCameraTrajectory();
  }

  core::Trajectory keyframes() {
    const py::gil_scoped_release unlocked;
    const std::lock_guard lock(mutex_);
    return slam_->keyFrameTrajectory();
  }

  py::object denseMap() { return denseMapToNumpy(finishedDenseMap()); }

  py::object objects() { return mapObjectsToNumpy(finishedDenseMap().objects); }

  std::uintmax_t saveMap(const std::filesystem::path& file) {
    const py::gil_scoped_release unlocked;
    const std::lock_guard lock(mutex_);
    return slam_->saveMap(file);
  }

  [[nodiscard]] std::size_t loadedPoints() const {
    const auto& loaded = slam_->loadedMap();
    return loaded ? loaded->contents.points.size() : 0;
  }
  [[nodiscard]] std::size_t loadedPointsLeft() {
    const std::lock_guard lock(mutex_);
    return slam_->loadedPointsLeft();
  }

  [[nodiscard]] bool finished() {
    const std::lock_guard lock(mutex_);
    return slam_->finished();
  }
  [[nodiscard]] std::size_t numKeyFrames() const { return slam_->numKeyFrames(); }
  [[nodiscard]] std::size_t numMapPoints() const { return slam_->numMapPoints(); }
  [[nodiscard]] const core::Camera& camera() const { return camera_; }
  [[nodiscard]] const std::string& maskSource() const { return mask_source_; }
  [[nodiscard]] const std::string& loopDetectorName() const { return loop_detector_; }

 private:
  core::Camera camera_;
  std::string mask_source_;
  std::string loop_detector_;
  std::mutex mutex_;
  std::optional<double> last_timestamp_;
  std::unique_ptr<system::StreamingSlam> slam_;
  std::optional<dense::DenseMap> dense_map_;

  // Built once: after finish() the map does not change.
  const dense::DenseMap& finishedDenseMap() {
    const py::gil_scoped_release unlocked;
    const std::lock_guard lock(mutex_);
    if (!dense_map_) dense_map_ = slam_->denseMap();
    return *dense_map_;
  }
};

std::unique_ptr<System> makeSystem(
    const core::Camera& camera, const std::string& seg, const std::string& loop_detector,
    bool deterministic, bool loop_closing, int features, int mask_dilation, bool build_map,
    std::uint64_t seed, const std::filesystem::path& model_config,
    const std::optional<std::filesystem::path>& model,
    const std::optional<std::filesystem::path>& vocabulary,
    const std::filesystem::path& backbone_config,
    const std::optional<std::filesystem::path>& backbone_model, int network_interval,
    int network_latency, const std::string& camera_motion,
    const std::optional<std::filesystem::path>& load_map, bool localize_only) {
  const SystemSettings settings{
      seg,           loop_detector,   deterministic,  loop_closing,     features,
      mask_dilation, build_map,       seed,           model_config,     model,
      vocabulary,    backbone_config, backbone_model, network_interval, network_latency,
      camera_motion, load_map,        localize_only};
  const py::gil_scoped_release unlocked;  // networks and the vocabulary load
  return std::make_unique<System>(camera, settings);
}

void bindTrackingState(py::module_& module) {
  py::enum_<tracking::TrackingState>(module, "TrackingState", "Where tracking stands.")
      .value("NOT_INITIALISED", tracking::TrackingState::kNotInitialised,
             "No map yet (too few depths on the frames so far).")
      .value("OK", tracking::TrackingState::kOk, "The frame has a pose.")
      .value("LOST", tracking::TrackingState::kLost,
             "The frame could not be placed; later frames try relocalisation.");
}

void bindTrackResult(py::module_& module) {
  py::class_<TrackResult>(module, "TrackResult", "What System.track made of a frame.")
      .def_readonly("frame_id", &TrackResult::frame_id, "0, 1, ... in the order of the calls.")
      .def_readonly("timestamp", &TrackResult::timestamp)
      .def_readonly("state", &TrackResult::state)
      .def_readonly("pose", &TrackResult::pose,
                    "float64 (4, 4) camera-to-world as tracked, or None when not tracked.")
      .def_readonly("mask", &TrackResult::mask,
                    "uint8 (H, W) dynamic mask used (255 = dynamic, before dilation), or None.")
      .def_readonly("labels", &TrackResult::labels,
                    "uint8 (H, W) semantic labels (segslam.SEMANTIC_CLASSES) carried from the "
                    "network, or None.")
      .def_readonly("keyframe", &TrackResult::keyframe, "Whether the frame became a keyframe.")
      .def_readonly("keypoints", &TrackResult::keypoints)
      .def_readonly("matches", &TrackResult::matches, "Map points used for the pose.")
      .def_readonly("tracking_ms", &TrackResult::tracking_ms,
                    "C++ time on the frame: masks, extraction, tracking (and, deterministic, "
                    "local mapping).")
      .def_readonly("mask_ms", &TrackResult::mask_ms)
      .def_readonly("pipeline_ms", &TrackResult::pipeline_ms,
                    "Wall time of the whole C++ pipeline call: tracking_ms, and handing late "
                    "masks and keyframes over to mapping and the dense map (work `segslam run` "
                    "does per frame too).")
      .def_property_readonly(
          "ok", [](const TrackResult& r) { return r.state == tracking::TrackingState::kOk; });
}

}  // namespace

void bindSystem(py::module_& module) {
  bindTrackingState(module);
  bindTrackResult(module);
  const system::SlamOptions defaults;
  py::class_<System>(module, "System",
                     "The SLAM pipeline of `segslam run` (masks, tracking, local mapping, loop "
                     "closing, dense map) for frames handed over one at a time.")
      .def(py::init(&makeSystem), py::arg("camera"), py::kw_only(), py::arg("seg") = "auto",
           py::arg("loop_detector") = "auto", py::arg("deterministic") = false,
           py::arg("loop_closing") = true, py::arg("features") = defaults.orb.num_features,
           py::arg("mask_dilation") = defaults.mask_dilation_px, py::arg("build_map") = true,
           py::arg("seed") = 0, py::arg("model_config") = defaultSegmentationConfig(),
           py::arg("model") = py::none(), py::arg("vocabulary") = py::none(),
           py::arg("backbone_config") = defaultBackboneConfig(),
           py::arg("backbone_model") = py::none(), py::arg("network_interval") = 5,
           py::arg("network_latency") = 0, py::arg("camera_motion") = "rigid",
           py::arg("load_map") = py::none(), py::arg("localize_only") = false,
           "Options as `segslam run`'s: seg is auto, none, oracle (the mask passed to track), "
           "semantic, geometric or fused; loop_detector auto, bow, vote or cnn; deterministic "
           "runs local mapping, loop closing and the network inline (reproducible); load_map "
           "starts in a saved map (`segslam run --save-map` or save_map), whose dense map "
           "carries on; localize_only tracks in it without changing it.")
      .def("track", &System::track, py::arg("timestamp"), py::arg("rgb"), py::arg("depth"),
           py::arg("mask") = py::none(),
           "Tracks one frame: rgb uint8 (H, W, 3); depth uint16 (raw, the camera's depth factor) "
           "or float32 (metres); mask None or uint8/bool (H, W), non-zero = dynamic, added to "
           "the configured masks (the only mask with seg='oracle'). Timestamps must increase.")
      .def("finish", &System::finish,
           "Waits for local mapping and loop closing; no frame can be tracked afterwards.")
      .def("trajectory", &System::trajectory,
           "Every tracked frame at its current (after finish(): final) pose, smoothed under a "
           "camera moving at near-constant velocity (CameraTrajectory.txt of `segslam run`).")
      .def("tracked_trajectory", &System::trackedTrajectory,
           "Every tracked frame at its current pose as tracked, not smoothed "
           "(CameraTrajectoryTracked.txt).")
      .def("keyframes", &System::keyframes, "The keyframes' poses.")
      .def("dense_map", &System::denseMap,
           "The dense map at the keyframes' final poses, with its objects (finishes the run "
           "first).")
      .def("objects", &System::objects,
           "The dense map's objects (segslam.MapObject list; finishes the run first).")
      .def("save_map", &System::saveMap, py::arg("path"),
           "Writes the SLAM map for `segslam run --load-map` or System(load_map=...) "
           "(finishes the run first); returns the file's size in bytes.")
      .def("__enter__", [](System& system) -> System& { return system; })
      .def("__exit__", [](System& system, const py::args&) { system.finish(); })
      .def_property_readonly("finished", &System::finished)
      .def_property_readonly("num_keyframes", &System::numKeyFrames)
      .def_property_readonly("num_map_points", &System::numMapPoints)
      .def_property_readonly("loaded_points", &System::loadedPoints,
                             "Points of the loaded map (0 without one).")
      .def_property_readonly("loaded_points_left", &System::loadedPointsLeft,
                             "Loaded points still in the map (the others were seen through, "
                             "on a moving object, or merged).")
      .def_property_readonly("camera", &System::camera)
      .def_property_readonly("mask_source", &System::maskSource,
                             "The masks in use ('auto' resolved).")
      .def_property_readonly("loop_detector", &System::loopDetectorName,
                             "The loop detector in use ('auto' resolved; 'none' without loop "
                             "closing).");
}

}  // namespace segslam::python
