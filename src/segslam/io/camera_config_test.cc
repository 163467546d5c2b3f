#include "segslam/io/camera_config.h"

#include <gtest/gtest.h>

#include "segslam/io/io_test_support.h"
#include "segslam/testing/test_support.h"

namespace segslam::io {
namespace {

using testing::contains;
using testing::errorMessage;

std::string yamlError(std::string_view text) {
  return errorMessage([&] { (void)parseCameraYaml(text, "d/camera.yaml"); });
}

TEST(CameraConfig, PresetsHaveThePublishedCalibration) {
  EXPECT_EQ(cameraPresetNames(),
            (std::vector<std::string>{"freiburg1", "freiburg2", "freiburg3", "bonn"}));
  const auto fr1 = cameraPreset("freiburg1");
  ASSERT_TRUE(fr1);
  EXPECT_EQ(fr1->name, "freiburg1");
  EXPECT_DOUBLE_EQ(fr1->fx, 517.306408);
  EXPECT_DOUBLE_EQ(fr1->cy, 255.313989);
  EXPECT_DOUBLE_EQ(fr1->distortion[4], 1.163314);
  EXPECT_EQ(fr1->width, 640);
  EXPECT_EQ(fr1->height, 480);
  EXPECT_DOUBLE_EQ(cameraPreset("freiburg2")->depth_factor, 5208.0);
  EXPECT_FALSE(cameraPreset("freiburg3")->hasDistortion());
  EXPECT_FALSE(cameraPreset("kinect"));
  const auto bonn = cameraPreset("bonn");
  ASSERT_TRUE(bonn);
  EXPECT_DOUBLE_EQ(bonn->fx, 542.822841);
  EXPECT_DOUBLE_EQ(bonn->fy, 542.576870);
  EXPECT_DOUBLE_EQ(bonn->cx, 315.593520);
  EXPECT_DOUBLE_EQ(bonn->cy, 237.756098);
  EXPECT_DOUBLE_EQ(bonn->distortion[0], 0.039903);
  EXPECT_DOUBLE_EQ(bonn->distortion[1], -0.099343);
  EXPECT_DOUBLE_EQ(bonn->distortion[3], -0.000144);
  EXPECT_DOUBLE_EQ(bonn->depth_factor, 5000.0);
  EXPECT_DOUBLE_EQ(requireCameraPreset("freiburg3").fy, 539.2);
  // The structured-light cameras' rolling shutter (bench/results/rolling_shutter.md).
  for (const auto& name : cameraPresetNames()) {
    EXPECT_DOUBLE_EQ(requireCameraPreset(name).rolling_shutter_readout_s, 0.02) << name;
  }
  EXPECT_DOUBLE_EQ(core::Camera{}.rolling_shutter_readout_s, 0.0);
  EXPECT_EQ(errorMessage([] { (void)requireCameraPreset("fr1"); }),
            "unknown camera preset 'fr1' (known: freiburg1, freiburg2, freiburg3, bonn)");
}

TEST(CameraConfig, PresetNameFromDatasetFolderName) {
  EXPECT_EQ(presetNameForDataset("/data/rgbd_dataset_freiburg2_desk"), "freiburg2");
  EXPECT_EQ(presetNameForDataset("/data/tum_fr1_xyz_300"), "freiburg1");
  EXPECT_EQ(presetNameForDataset("/data/tum_fr1_xyz_300_walker"), "freiburg1");
  EXPECT_EQ(presetNameForDataset("/data/FR3-walking"), "freiburg3");
  EXPECT_EQ(presetNameForDataset("/data/rgbd_dataset_freiburg3_walking_xyz/"), "freiburg3");
  EXPECT_FALSE(presetNameForDataset("/data/tum_walking_xyz_frames"));
  EXPECT_FALSE(presetNameForDataset("/data/run_fr12"));
  EXPECT_FALSE(presetNameForDataset("/data/afr1"));
  EXPECT_FALSE(presetNameForDataset("/data/fr4_office"));
  EXPECT_EQ(presetNameForDataset("/data/rgbd_bonn_crowd"), "bonn");
  EXPECT_EQ(presetNameForDataset("/data/rgbd_bonn_crowd_300/"), "bonn");
  EXPECT_EQ(presetNameForDataset("/data/Bonn-balloon2"), "bonn");
  EXPECT_FALSE(presetNameForDataset("/data/bonnet"));
}

TEST(CameraConfig, YamlRoundTrip) {
  segslam::testing::ScopedTempDir temp;
  core::Camera camera;
  camera.name = "my_camera";
  camera.width = 320;
  camera.height = 240;
  camera.fx = 260.5;
  camera.fy = 261.25;
  camera.cx = 160.125;
  camera.cy = 119.875;
  camera.distortion = {0.1, -0.2, 0.001, -0.002, 0.3};
  camera.depth_factor = 1000.0;
  camera.fps = 15.0;
  camera.rolling_shutter_readout_s = 0.031;
  const auto file = temp.path() / "nested" / "camera.yaml";
  writeCameraYaml(file, camera);
  const core::Camera read = readCameraYaml(file);
  EXPECT_EQ(read.name, camera.name);
  EXPECT_EQ(read.width, camera.width);
  EXPECT_EQ(read.height, camera.height);
  EXPECT_DOUBLE_EQ(read.fx, camera.fx);
  EXPECT_DOUBLE_EQ(read.fy, camera.fy);
  EXPECT_DOUBLE_EQ(read.cx, camera.cx);
  EXPECT_DOUBLE_EQ(read.cy, camera.cy);
  EXPECT_EQ(read.distortion, camera.distortion);
  EXPECT_DOUBLE_EQ(read.depth_factor, camera.depth_factor);
  EXPECT_DOUBLE_EQ(read.fps, camera.fps);
  EXPECT_DOUBLE_EQ(read.rolling_shutter_readout_s, camera.rolling_shutter_readout_s);
}

TEST(CameraConfig, PresetWithOverrides) {
  const core::Camera camera = parseCameraYaml(
      "camera:\n  preset: freiburg1\n  name: fr1_rescaled\n  fx: 500\n  fps: 15\n", "c.yaml");
  EXPECT_EQ(camera.name, "fr1_rescaled");
  EXPECT_DOUBLE_EQ(camera.fx, 500.0);
  EXPECT_DOUBLE_EQ(camera.fy, 516.469215);
  EXPECT_DOUBLE_EQ(camera.fps, 15.0);
  EXPECT_DOUBLE_EQ(camera.distortion[0], 0.262383);
  EXPECT_DOUBLE_EQ(camera.rolling_shutter_readout_s, 0.02);
  EXPECT_DOUBLE_EQ(
      parseCameraYaml("camera:\n  preset: bonn\n  rolling_shutter_readout: 0\n", "c.yaml")
          .rolling_shutter_readout_s,
      0.0);
  // Rows read from the last to the first: frames played backwards, a sensor mounted upside down.
  EXPECT_DOUBLE_EQ(
      parseCameraYaml("camera:\n  preset: bonn\n  rolling_shutter_readout: -0.02\n", "c.yaml")
          .rolling_shutter_readout_s,
      -0.02);
}

TEST(CameraConfig, FullDefinitionWithoutPreset) {
  const core::Camera camera = parseCameraYaml(
      "camera: {width: 64, height: 48, fx: 50, fy: 51, cx: 31.5, cy: 23.5, depth_factor: 1000}\n",
      "c.yaml");
  EXPECT_EQ(camera.width, 64);
  EXPECT_DOUBLE_EQ(camera.fy, 51.0);
  EXPECT_FALSE(camera.hasDistortion());
}

TEST(CameraConfig, MalformedYamlNamesFileAndLine) {
  EXPECT_TRUE(contains(yamlError("camera:\n  preset: freiburg1\n  fx: [1, 2\n"),
                       "d/camera.yaml:4: malformed YAML"));
  EXPECT_TRUE(
      contains(yamlError("camera:\n  fx: 1\n   fy: 2\n"), "d/camera.yaml:3: malformed YAML"));
}

TEST(CameraConfig, MissingMappingOrKeys) {
  EXPECT_EQ(yamlError(""), "d/camera.yaml: expected a top-level 'camera:' mapping");
  EXPECT_EQ(yamlError("cam:\n  preset: freiburg1\n"),
            "d/camera.yaml:1: expected a top-level 'camera:' mapping");
  EXPECT_EQ(yamlError("camera:\n  width: 640\n  height: 480\n  fx: 500\n"),
            "d/camera.yaml:2: camera.fy is missing (or give camera.preset)");
  EXPECT_EQ(errorMessage([] { (void)readCameraYaml("/nonexistent/camera.yaml"); }),
            "/nonexistent/camera.yaml: file not found");
}

TEST(CameraConfig, WrongTypesNameFileAndLine) {
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  fx: abc\n"),
            "d/camera.yaml:3: camera.fx has the wrong type: 'abc'");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  width: 640.5\n"),
            "d/camera.yaml:3: camera.width has the wrong type: '640.5'");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  cx: [1]\n"),
            "d/camera.yaml:3: camera.cx has the wrong type: '<not a scalar>'");
}

TEST(CameraConfig, ImpossibleValuesAreRejected) {
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  fx: -500\n"),
            "d/camera.yaml: camera.fx and fy must be positive and finite");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  fy: .inf\n"),
            "d/camera.yaml: camera.fx and fy must be positive and finite");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  depth_factor: 0\n"),
            "d/camera.yaml: camera.depth_factor must be positive and finite");
  // Found by fuzz/fuzz_camera_yaml: an infinite depth factor made every depth 0 m.
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  depth_factor: .inf\n"),
            "d/camera.yaml: camera.depth_factor must be positive and finite");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  fps: .inf\n"),
            "d/camera.yaml: camera.fps must be positive and finite");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  height: -1\n"),
            "d/camera.yaml: camera.width and height must be positive");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  cy: .nan\n"),
            "d/camera.yaml: camera.cx and cy must be finite");
  for (const char* readout : {"-0.04", "0.04", ".nan"}) {
    EXPECT_EQ(yamlError(std::string("camera:\n  preset: freiburg1\n  rolling_shutter_readout: ") +
                        readout + "\n"),
              "d/camera.yaml: camera.rolling_shutter_readout must be within one frame period "
              "(1 / fps) seconds of 0")
        << readout;
  }
}

TEST(CameraConfig, DistortionMustBeFiveNumbers) {
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg3\n  distortion: [0.1, 0.2, 0, 0]\n"),
            "d/camera.yaml:3: camera.distortion must be a list of 5 numbers [k1, k2, p1, p2, k3]");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg3\n  distortion: 0.1\n"),
            "d/camera.yaml:3: camera.distortion must be a list of 5 numbers [k1, k2, p1, p2, k3]");
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg3\n  distortion: [0.1, 0.2, 0, 0, x]\n"),
            "d/camera.yaml:3: camera.distortion has the wrong type: 'x'");
}

TEST(CameraConfig, UnknownKeysAndPresetsAreRejected) {
  EXPECT_EQ(yamlError("camera:\n  preset: freiburg1\n  fxx: 500\n"),
            "d/camera.yaml:3: camera.fxx is not a known key (known: preset, name, width, height, "
            "fx, fy, cx, cy, distortion, depth_factor, fps, rolling_shutter_readout)");
  EXPECT_EQ(yamlError("camera:\n  preset: kinect\n"),
            "d/camera.yaml:2: unknown camera preset 'kinect' (known: freiburg1, freiburg2, "
            "freiburg3, bonn)");
}

}  // namespace
}  // namespace segslam::io
