#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Which ONNX network gives the CNN place descriptors and which of its layers are compared: the
// method's VGG-16 is not available everywhere, so the backbone and its layers are configuration.
namespace segslam::place {

struct CnnLayer {
  std::string name;   // shown in tables and method names, e.g. "pool3"
  std::string layer;  // OpenCV dnn layer name whose output is read
  // Radius (input pixels) by which the static mask is eroded for the pooled descriptor: a
  // feature within about this distance of a moving object sees it through its receptive field.
  int erosion_px = 0;
};

struct CnnBackboneConfig {
  std::string name;
  std::filesystem::path model;  // as written in the file (relative: see resolveBackboneModelFile)
  cv::Size input_size;
  bool rgb = true;
  double scale = 1.0 / 255.0;  // applied to 8-bit values first, then (value - mean) / std
  cv::Scalar mean{0, 0, 0};
  cv::Scalar std{1, 1, 1};
  // Feature maps are kept per image area-averaged to at most this many cells (width x height),
  // which bounds the bytes stored per keyframe.
  cv::Size stored_grid{40, 30};
  // Cells (width x height) of the masked average pooling of the pooled descriptor.
  cv::Size pooling_grid{4, 3};
  std::vector<CnnLayer> layers;
};

// Reads a backbone config:
//
//   cnn_backbone:
//     name: tiny_darknet_imagenet
//     model: tiny_darknet_imagenet.onnx
//     input_width: 640
//     input_height: 480
//     color_order: rgb            # or bgr
//     scale: 0.00392156862745098
//     mean: [0, 0, 0]
//     std: [1, 1, 1]
//     stored_grid: [40, 30]
//     pooling_grid: [4, 3]
//     layers:
//       - {name: pool3, layer: "onnx_node_output_0!max_pooling2d_3", erosion_px: 16}
//
// Every problem (syntax, unknown key, wrong type, no layers, duplicate layer names) is a
// util::Error naming the file and line.
CnnBackboneConfig readCnnBackboneConfig(const std::filesystem::path& file);
CnnBackboneConfig parseCnnBackboneConfig(std::string_view text, const std::filesystem::path& file);

// The network file, first found of: `override_file` (a --model flag; must exist), the config's
// `model` (absolute, or relative to the config file's folder), and its file name in
// $SEGSLAM_MODEL_DIR. util::Error listing the places tried when none exists.
std::filesystem::path resolveBackboneModelFile(
    const CnnBackboneConfig& config, const std::filesystem::path& config_file,
    const std::optional<std::filesystem::path>& override_file);

}  // namespace segslam::place
