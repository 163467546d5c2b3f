#include "segslam/io/camera_config.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <string_view>
#include <system_error>

#include "segslam/io/dataset_name.h"
#include "segslam/util/error.h"
#include "segslam/util/text_file.h"
#include "segslam/util/yaml_document.h"

namespace segslam::io {

namespace {

// The colour cameras of TUM's Kinects and of Bonn's ASUS Xtion read their rows over ~20 ms of the
// 33 ms frame: the readout that gave the lowest ATE on tum_fr1_xyz_300 and rgbd_bonn_crowd_300
// (bench/results/rolling_shutter.md).
constexpr double kStructuredLightCameraReadoutS = 0.02;

core::Camera makeTumCamera(const std::string& name, double fx, double fy, double cx, double cy,
                           std::array<double, 5> distortion, double depth_factor) {
  core::Camera camera;
  camera.name = name;
  camera.width = 640;
  camera.height = 480;
  camera.fx = fx;
  camera.fy = fy;
  camera.cx = cx;
  camera.cy = cy;
  camera.distortion = distortion;
  camera.depth_factor = depth_factor;
  camera.fps = 30.0;
  camera.rolling_shutter_readout_s = kStructuredLightCameraReadoutS;
  return camera;
}

template <typename T>
T readScalar(const YAML::Node& node, const std::string& key, const std::filesystem::path& file) {
  return util::yamlValue<T>(node, "camera." + key, file);
}

template <typename T>
void readOptional(const YAML::Node& camera_node, const std::string& key,
                  const std::filesystem::path& file, T& value) {
  const YAML::Node node = camera_node[key];
  if (node) value = readScalar<T>(node, key, file);
}

std::array<double, 5> readDistortion(const YAML::Node& node, const std::filesystem::path& file) {
  if (!node.IsSequence() || node.size() != 5) {
    util::failAt(file, util::yamlLine(node),
                 "camera.distortion must be a list of 5 numbers [k1, k2, p1, p2, k3]");
  }
  std::array<double, 5> d{};
  for (std::size_t i = 0; i < 5; ++i) d[i] = readScalar<double>(node[i], "distortion", file);
  return d;
}

void rejectUnknownKeys(const YAML::Node& camera_node, const std::filesystem::path& file) {
  static constexpr std::array<std::string_view, 12> kKeys = {
      "preset", "name", "width",      "height",       "fx",  "fy",
      "cx",     "cy",   "distortion", "depth_factor", "fps", "rolling_shutter_readout"};
  util::rejectUnknownYamlKeys(camera_node, kKeys, "camera.", file);
}

core::Camera startingCamera(const YAML::Node& camera_node, const std::filesystem::path& file) {
  const YAML::Node preset_node = camera_node["preset"];
  if (!preset_node) return core::Camera{};
  try {
    return requireCameraPreset(readScalar<std::string>(preset_node, "preset", file));
  } catch (const util::Error& e) {
    util::failAt(file, util::yamlLine(preset_node), e.what());
  }
}

void requireIntrinsics(const YAML::Node& camera_node, const std::filesystem::path& file) {
  if (camera_node["preset"]) return;
  for (const char* key : {"width", "height", "fx", "fy", "cx", "cy", "depth_factor"}) {
    if (!camera_node[key]) {
      util::failAt(file, util::yamlLine(camera_node),
                   fmt::format("camera.{} is missing (or give camera.preset)", key));
    }
  }
}

}  // namespace

std::optional<core::Camera> cameraPreset(const std::string& name) {
  if (name == "freiburg1") {
    return makeTumCamera(name, 517.306408, 516.469215, 318.643040, 255.313989,
                         {0.262383, -0.953104, -0.005358, 0.002628, 1.163314}, 5000.0);
  }
  if (name == "freiburg2") {
    return makeTumCamera(name, 520.908620, 521.007327, 325.141442, 249.701764,
                         {0.231222, -0.784899, -0.003257, -0.000105, 0.917205}, 5208.0);
  }
  if (name == "freiburg3") {
    return makeTumCamera(name, 535.4, 539.2, 320.1, 247.6, {0.0, 0.0, 0.0, 0.0, 0.0}, 5000.0);
  }
  if (name == "bonn") {
    // The Bonn RGB-D Dynamic dataset's ASUS Xtion, as its README gives it.
    return makeTumCamera(name, 542.822841, 542.576870, 315.593520, 237.756098,
                         {0.039903, -0.099343, -0.000730, -0.000144, 0.0}, 5000.0);
  }
  return std::nullopt;
}

std::vector<std::string> cameraPresetNames() {
  return {"freiburg1", "freiburg2", "freiburg3", "bonn"};
}

core::Camera requireCameraPreset(const std::string& name) {
  auto preset = cameraPreset(name);
  if (!preset) {
    throw util::Error(fmt::format("unknown camera preset '{}' (known: {})", name,
                                  fmt::join(cameraPresetNames(), ", ")));
  }
  return *preset;
}

std::optional<std::string> presetNameForDataset(const std::filesystem::path& dataset_folder) {
  const std::string name = datasetFolderName(dataset_folder);
  for (const char* prefix : {"freiburg", "fr"}) {
    for (const char digit : {'1', '2', '3'}) {
      if (hasNameToken(name, prefix + std::string(1, digit)))
        return "freiburg" + std::string(1, digit);
    }
  }
  if (hasNameToken(name, "bonn")) return "bonn";
  return std::nullopt;
}

core::Camera readCameraYaml(const std::filesystem::path& file) {
  return parseCameraYaml(util::readTextFile(file), file);
}

core::Camera parseCameraYaml(std::string_view text, const std::filesystem::path& file) {
  const YAML::Node root = util::parseYaml(text, file);
  if (!root.IsMap() || !root["camera"] || !root["camera"].IsMap()) {
    util::failAt(file, util::yamlLine(root), "expected a top-level 'camera:' mapping");
  }
  const YAML::Node node = root["camera"];
  rejectUnknownKeys(node, file);
  core::Camera camera = startingCamera(node, file);
  requireIntrinsics(node, file);
  readOptional(node, "name", file, camera.name);
  readOptional(node, "width", file, camera.width);
  readOptional(node, "height", file, camera.height);
  readOptional(node, "fx", file, camera.fx);
  readOptional(node, "fy", file, camera.fy);
  readOptional(node, "cx", file, camera.cx);
  readOptional(node, "cy", file, camera.cy);
  readOptional(node, "depth_factor", file, camera.depth_factor);
  readOptional(node, "fps", file, camera.fps);
  readOptional(node, "rolling_shutter_readout", file, camera.rolling_shutter_readout_s);
  if (node["distortion"]) camera.distortion = readDistortion(node["distortion"], file);
  validateCamera(camera, file);
  return camera;
}

core::Camera readCalibrationTxt(const std::filesystem::path& file, int width, int height) {
  constexpr std::string_view kFormat = "fx fy cx cy";
  const auto rows = util::readTextRows(file);
  if (rows.size() != 1) {
    util::failAt(file,
                 fmt::format("expected one line '{}' but found {} line(s)", kFormat, rows.size()));
  }
  const util::TextRow& row = rows.front();
  util::requireFieldCount(row, 4, file, kFormat);
  core::Camera camera;
  camera.name = "calibration.txt";
  camera.width = width;
  camera.height = height;
  camera.fx = util::parseDouble(row.fields[0], file, row.line, "fx");
  camera.fy = util::parseDouble(row.fields[1], file, row.line, "fy");
  camera.cx = util::parseDouble(row.fields[2], file, row.line, "cx");
  camera.cy = util::parseDouble(row.fields[3], file, row.line, "cy");
  camera.depth_factor = 5000.0;
  camera.fps = 30.0;
  validateCamera(camera, file);
  return camera;
}

void writeCameraYaml(const std::filesystem::path& file, const core::Camera& camera) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "camera" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << camera.name;
  out << YAML::Key << "width" << YAML::Value << camera.width;
  out << YAML::Key << "height" << YAML::Value << camera.height;
  out << YAML::Key << "fx" << YAML::Value << camera.fx;
  out << YAML::Key << "fy" << YAML::Value << camera.fy;
  out << YAML::Key << "cx" << YAML::Value << camera.cx;
  out << YAML::Key << "cy" << YAML::Value << camera.cy;
  out << YAML::Key << "distortion" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (double d : camera.distortion) out << d;
  out << YAML::EndSeq;
  out << YAML::Key << "depth_factor" << YAML::Value << camera.depth_factor;
  out << YAML::Key << "fps" << YAML::Value << camera.fps;
  out << YAML::Key << "rolling_shutter_readout" << YAML::Value << camera.rolling_shutter_readout_s;
  out << YAML::EndMap << YAML::EndMap;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream stream(file);
  stream
      << "# segslam camera settings (pinhole + k1 k2 p1 p2 k3; metres = depth / depth_factor;\n"
      << "# rolling_shutter_readout: seconds from the first row to the last, 0 = global shutter,\n"
      << "# negative = the last row read first)\n"
      << out.c_str() << "\n";
  if (!stream) util::failAt(file, "cannot write");
}

void validateCamera(const core::Camera& camera, const std::filesystem::path& source) {
  auto fail = [&](const std::string& what) { util::failAt(source, "camera." + what); };
  if (camera.width <= 0 || camera.height <= 0) fail("width and height must be positive");
  auto positive = [](double value) { return value > 0.0 && std::isfinite(value); };
  if (!positive(camera.fx) || !positive(camera.fy)) fail("fx and fy must be positive and finite");
  if (!std::isfinite(camera.cx) || !std::isfinite(camera.cy)) fail("cx and cy must be finite");
  if (!positive(camera.depth_factor)) fail("depth_factor must be positive and finite");
  if (!positive(camera.fps)) fail("fps must be positive and finite");
  if (!(std::abs(camera.rolling_shutter_readout_s) <= 1.0 / camera.fps)) {
    fail("rolling_shutter_readout must be within one frame period (1 / fps) seconds of 0");
  }
  for (double d : camera.distortion) {
    if (!std::isfinite(d)) fail("distortion must be finite");
  }
}

}  // namespace segslam::io
