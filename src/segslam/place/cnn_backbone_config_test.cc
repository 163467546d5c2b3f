#include "segslam/place/cnn_backbone_config.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::place {
namespace {

constexpr const char* kValid = R"(cnn_backbone:
  name: tiny
  model: tiny.onnx
  input_width: 64
  input_height: 48
  color_order: bgr
  std: [2, 2, 2]
  stored_grid: [8, 6]
  pooling_grid: [2, 2]
  layers:
    - {name: pool1, layer: "net!pool_1", erosion_px: 3}
    - {name: global, layer: gap}
)";

std::string errorOf(const std::string& text) {
  try {
    parseCnnBackboneConfig(text, "backbone.yaml");
  } catch (const util::Error& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(CnnBackboneConfig, ReadsEveryField) {
  const CnnBackboneConfig config = parseCnnBackboneConfig(kValid, "backbone.yaml");
  EXPECT_EQ(config.name, "tiny");
  EXPECT_EQ(config.input_size, cv::Size(64, 48));
  EXPECT_FALSE(config.rgb);
  EXPECT_DOUBLE_EQ(config.scale, 1.0 / 255.0);
  EXPECT_EQ(config.std, cv::Scalar(2, 2, 2));
  EXPECT_EQ(config.stored_grid, cv::Size(8, 6));
  EXPECT_EQ(config.pooling_grid, cv::Size(2, 2));
  ASSERT_EQ(config.layers.size(), 2u);
  EXPECT_EQ(config.layers[0].layer, "net!pool_1");
  EXPECT_EQ(config.layers[0].erosion_px, 3);
  EXPECT_EQ(config.layers[1].erosion_px, 0);
}

TEST(CnnBackboneConfig, ShippedTinyDarknetConfigIsValid) {
  const auto file =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/tiny_darknet_imagenet.yaml";
  const CnnBackboneConfig config = readCnnBackboneConfig(file);
  EXPECT_EQ(config.input_size, cv::Size(320, 240));
  EXPECT_EQ(config.stored_grid, cv::Size(20, 15));
  ASSERT_EQ(config.layers.size(), 6u);
  EXPECT_EQ(config.layers[2].name, "pool3");
  EXPECT_EQ(config.layers[2].layer, "onnx_node_output_0!max_pooling2d_3");
}

TEST(CnnBackboneConfig, BadFilesNameTheFileAndLine) {
  const std::string text = kValid;
  EXPECT_EQ(errorOf(replaced(text, "  name: tiny\n", "")),
            "backbone.yaml:2: cnn_backbone.name is missing");
  EXPECT_EQ(errorOf(replaced(text, "input_width: 64", "input_width: wide")),
            "backbone.yaml:4: cnn_backbone.input_width has the wrong type: 'wide'");
  EXPECT_EQ(errorOf(replaced(text, "color_order: bgr", "color_order: hsv")),
            "backbone.yaml:6: cnn_backbone.color_order must be rgb or bgr, not 'hsv'");
  EXPECT_EQ(errorOf(replaced(text, "stored_grid: [8, 6]", "stored_grid: [8]")),
            "backbone.yaml:8: cnn_backbone.stored_grid must be [width, height]");
  EXPECT_EQ(errorOf(replaced(text, "pooling_grid: [2, 2]", "pooling_grid: [9, 2]")),
            "backbone.yaml:9: cnn_backbone.pooling_grid must not be finer than "
            "cnn_backbone.stored_grid");
  EXPECT_EQ(errorOf(replaced(text, "{name: global, layer: gap}", "{name: pool1, layer: gap}")),
            "backbone.yaml:12: layer name 'pool1' appears twice");
  EXPECT_EQ(errorOf(replaced(text, "{name: global, layer: gap}", "{name: global}")),
            "backbone.yaml:12: cnn_backbone.layers entry layer is missing");
  EXPECT_EQ(errorOf(replaced(text, "erosion_px: 3", "erosion_px: -1")),
            "backbone.yaml:11: cnn_backbone.layers entry erosion_px must not be negative");
  EXPECT_NE(errorOf(replaced(text, "erosion_px: 3", "radius: 3")).find("backbone.yaml:11:"),
            std::string::npos);
  EXPECT_EQ(errorOf(text.substr(0, text.find("  layers:"))),
            "backbone.yaml:2: cnn_backbone.layers is missing");
  EXPECT_EQ(errorOf("segmentation_model: {}\n"),
            "backbone.yaml:1: expected a top-level 'cnn_backbone:' mapping");
  EXPECT_NE(errorOf("cnn_backbone: [\n").find("backbone.yaml:"), std::string::npos);
}

TEST(CnnBackboneConfig, ModelFileFromFlagBesideConfigOrModelDir) {
  segslam::testing::ScopedTempDir dir;
  const auto config_file = dir.path() / "configs/backbone.yaml";
  std::filesystem::create_directories(config_file.parent_path());
  const CnnBackboneConfig config = parseCnnBackboneConfig(kValid, config_file);
  EXPECT_THROW(resolveBackboneModelFile(config, config_file, std::nullopt), util::Error);
  std::ofstream(dir.path() / "configs/tiny.onnx") << "x";
  EXPECT_EQ(resolveBackboneModelFile(config, config_file, std::nullopt),
            dir.path() / "configs/tiny.onnx");
  std::ofstream(dir.path() / "other.onnx") << "x";
  EXPECT_EQ(resolveBackboneModelFile(config, config_file, dir.path() / "other.onnx"),
            dir.path() / "other.onnx");
  EXPECT_THROW(resolveBackboneModelFile(config, config_file, dir.path() / "missing.onnx"),
               util::Error);
}

}  // namespace
}  // namespace segslam::place
