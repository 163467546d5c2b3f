#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <vector>

#include "segslam/place/cnn_backbone_config.h"

namespace segslam::place {

// Runs a backbone once per image and reads the outputs of the configured layers.
class CnnFeatureExtractor {
 public:
  // Throws util::Error naming the model file when it cannot be loaded or lacks a layer.
  CnnFeatureExtractor(CnnBackboneConfig config, const std::filesystem::path& model_file);

  [[nodiscard]] const CnnBackboneConfig& config() const { return config_; }

  // One blob per configured layer, in the config's order: 1 x C x H x W, or 1 x C for layers
  // without a spatial extent (global pooling). `bgr` is CV_8UC3 of any size.
  [[nodiscard]] std::vector<cv::Mat> extract(const cv::Mat& bgr);

 private:
  CnnBackboneConfig config_;
  cv::dnn::Net net_;
  std::vector<cv::String> layer_names_;
};

}  // namespace segslam::place
