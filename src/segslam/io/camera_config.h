#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "segslam/core/camera.h"

namespace segslam::io {

// Built-in camera presets: the TUM RGB-D benchmark's "freiburg1", "freiburg2", "freiburg3" and the
// Bonn RGB-D Dynamic dataset's "bonn", with the intrinsics and distortion their sites publish.
std::optional<core::Camera> cameraPreset(const std::string& name);
std::vector<std::string> cameraPresetNames();

// The preset called `name`; throws util::Error listing the known presets when there is none.
core::Camera requireCameraPreset(const std::string& name);

// Guesses the preset from a dataset folder name: "freiburg<N>" or "fr<N>" ("rgbd_dataset_
// freiburg2_desk", "tum_fr1_xyz_300") names a TUM camera, "bonn" ("rgbd_bonn_crowd") the Bonn
// one (io::hasNameToken). Returns nothing when the name does not say.
std::optional<std::string> presetNameForDataset(const std::filesystem::path& dataset_folder);

// Reads camera settings from YAML:
//   camera:
//     preset: freiburg1        # optional: start from a preset, then override any key below
//     name: my_camera
//     width: 640
//     height: 480
//     fx: 517.3  fy: 516.5  cx: 318.6  cy: 255.3
//     distortion: [k1, k2, p1, p2, k3]   # optional, default zeros
//     depth_factor: 5000                 # raw depth units per metre
//     fps: 30
//     rolling_shutter_readout: 0.02      # optional, seconds from the first row to the last;
//                                        # 0 (the default without a preset) = global shutter;
//                                        # negative: the last row is read first
// Throws util::Error naming the file (and line) on malformed YAML, missing or unknown keys, wrong
// types or impossible values.
core::Camera readCameraYaml(const std::filesystem::path& file);

// The same for the text of such a file; `name` is the file named in error messages.
core::Camera parseCameraYaml(std::string_view text, const std::filesystem::path& name);

// Reads an ETH3D SLAM benchmark calibration.txt: one line `fx fy cx cy` of the undistorted
// colour images, which are `width` x `height` pixels; depth is in 1/5000 m as in TUM, the rate 30
// Hz (playback follows the timestamps). Throws util::Error naming the file (and line) when it is
// not that.
core::Camera readCalibrationTxt(const std::filesystem::path& file, int width, int height);

void writeCameraYaml(const std::filesystem::path& file, const core::Camera& camera);

// Throws util::Error (prefixed with `source`) when a value is impossible.
void validateCamera(const core::Camera& camera, const std::filesystem::path& source);

}  // namespace segslam::io
