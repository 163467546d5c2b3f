#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// How to run an ONNX semantic segmentation network: everything that differs between networks
// lives in a small YAML file, so that any network OpenCV's dnn module can read can be plugged in.
namespace segslam::segmentation {

enum class TensorLayout { kNchw, kNhwc };

struct ModelConfig {
  std::string name;
  std::filesystem::path model;  // as written in the file (relative: see resolveModelFile)
  cv::Size input_size;          // the network's input, the frame is resized to it
  TensorLayout layout = TensorLayout::kNchw;
  bool rgb = true;             // channel order the network expects (frames are BGR)
  double scale = 1.0 / 255.0;  // applied to 8-bit pixel values first
  cv::Scalar mean{0, 0, 0};    // then (value - mean) / std per channel, in the network's order
  cv::Scalar std{1, 1, 1};
  std::string input;                         // input blob name; empty: the network's only input
  std::string output;                        // output blob name; empty: the network's last layer
  std::vector<std::string> classes;          // class name per output channel
  std::vector<std::string> dynamic_classes;  // classes that move (masked for SLAM)

  // Output channel indices of the dynamic classes.
  [[nodiscard]] std::vector<int> dynamicClassIndices() const;
};

// Reads a model config:
//
//   segmentation_model:
//     name: espnetv2_voc_384
//     model: espnetv2_voc_384.onnx
//     input_width: 384
//     input_height: 384
//     layout: nchw            # or nhwc
//     color_order: rgb        # or bgr
//     scale: 0.00392156862745098
//     mean: [0.485, 0.456, 0.406]
//     std: [0.229, 0.224, 0.225]
//     output: logits
//     classes: [background, ..., person, ...]
//     dynamic_classes: [person]
//
// Every problem (syntax, unknown key, wrong type, a dynamic class that is not a class) is a
// util::Error naming the file and line.
ModelConfig readModelConfig(const std::filesystem::path& file);
ModelConfig parseModelConfig(std::string_view text, const std::filesystem::path& file);

// The network file to load, first found of: `override_file` (a --model flag; must exist), the
// config's `model` (absolute, or relative to the config file's folder), and the config's file
// name in $SEGSLAM_MODEL_DIR. util::Error listing the places tried when none exists.
std::filesystem::path resolveModelFile(const ModelConfig& config,
                                       const std::filesystem::path& config_file,
                                       const std::optional<std::filesystem::path>& override_file);

}  // namespace segslam::segmentation
