#include "segslam/segmentation/model_config.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::segmentation {
namespace {

using testing::ScopedTempDir;

constexpr const char* kValid = R"(segmentation_model:
  name: tiny
  model: tiny.onnx
  input_width: 64
  input_height: 32
  color_order: bgr
  mean: [1, 2, 3]
  std: [2, 2, 2]
  classes: [background, chair, person]
  dynamic_classes: [person, chair]
)";

std::string errorOf(const std::string& text) {
  try {
    parseModelConfig(text, "model.yaml");
  } catch (const util::Error& e) {
    return e.what();
  }
  return "";
}

TEST(ModelConfig, ReadsEveryField) {
  const ModelConfig config = parseModelConfig(kValid, "model.yaml");
  EXPECT_EQ(config.name, "tiny");
  EXPECT_EQ(config.input_size, cv::Size(64, 32));
  EXPECT_EQ(config.layout, TensorLayout::kNchw);
  EXPECT_FALSE(config.rgb);
  EXPECT_DOUBLE_EQ(config.scale, 1.0 / 255.0);
  EXPECT_EQ(config.mean, cv::Scalar(1, 2, 3));
  EXPECT_EQ(config.dynamicClassIndices(), (std::vector<int>{2, 1}));
}

TEST(ModelConfig, ShippedEspnetConfigIsValid) {
  const auto file =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";
  const ModelConfig config = readModelConfig(file);
  EXPECT_EQ(config.classes.size(), 21u);
  EXPECT_EQ(config.dynamicClassIndices(), std::vector<int>{15});
  EXPECT_EQ(config.output, "logits");
}

TEST(ModelConfig, BadFilesNameTheFileAndLine) {
  std::string text = kValid;
  EXPECT_EQ(errorOf(text + "  colour: rgb\n"),
            "model.yaml:11: segmentation_model.colour is not a known key (known: name, model, "
            "input_width, input_height, layout, color_order, scale, mean, std, input, output, "
            "classes, dynamic_classes)");
  EXPECT_EQ(errorOf(std::string(kValid).replace(text.find("[person, chair]"), 15, "[dog]")),
            "model.yaml:10: dynamic class 'dog' is not one of segmentation_model.classes");
  EXPECT_EQ(errorOf(std::string(kValid).replace(text.find("64"), 2, "wide")),
            "model.yaml:4: segmentation_model.input_width has the wrong type: 'wide'");
  EXPECT_EQ(errorOf(std::string(kValid).replace(text.find("bgr"), 3, "hsv")),
            "model.yaml:6: segmentation_model.color_order must be rgb or bgr, not 'hsv'");
  EXPECT_EQ(errorOf("camera:\n  fx: 1\n"),
            "model.yaml:1: expected a top-level 'segmentation_model:' mapping");
  EXPECT_NE(errorOf("segmentation_model: [\n").find("model.yaml:"), std::string::npos);
}

TEST(ModelConfig, ModelFileIsFoundBesideTheConfigOrInTheModelDir) {
  const ScopedTempDir dir;
  const ModelConfig config = parseModelConfig(kValid, "model.yaml");
  const auto config_file = dir.path() / "configs" / "model.yaml";
  std::filesystem::create_directories(dir.path() / "configs");
  std::filesystem::create_directories(dir.path() / "models");
  std::ofstream(dir.path() / "models" / "tiny.onnx") << "x";
  ::unsetenv("SEGSLAM_MODEL_DIR");
  EXPECT_THROW(resolveModelFile(config, config_file, std::nullopt), util::Error);
  ::setenv("SEGSLAM_MODEL_DIR", (dir.path() / "models").c_str(), 1);
  EXPECT_EQ(resolveModelFile(config, config_file, std::nullopt), dir.path() / "models/tiny.onnx");
  ::unsetenv("SEGSLAM_MODEL_DIR");
  std::ofstream(dir.path() / "configs" / "tiny.onnx") << "x";
  EXPECT_EQ(resolveModelFile(config, config_file, std::nullopt), dir.path() / "configs/tiny.onnx");
  EXPECT_EQ(resolveModelFile(config, config_file, dir.path() / "models/tiny.onnx"),
            dir.path() / "models/tiny.onnx");
  try {
    resolveModelFile(config, config_file, dir.path() / "missing.onnx");
    ADD_FAILURE() << "a missing --model file must be an error";
  } catch (const util::Error& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir.path() / "missing.onnx").string() + ": segmentation model file not found");
  }
}

}  // namespace
}  // namespace segslam::segmentation
