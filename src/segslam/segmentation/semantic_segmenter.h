#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <vector>

#include "segslam/segmentation/fast_dnn_layers.h"
#include "segslam/segmentation/model_config.h"

namespace segslam::segmentation {

// One frame's semantic segmentation at the frame's size.
struct SemanticMasks {
  cv::Mat labels;   // CV_8UC1 class index per pixel (ModelConfig::classes)
  cv::Mat dynamic;  // CV_8UC1, 255 where the class is dynamic
};

// Runs an ONNX segmentation network through OpenCV's dnn module as its ModelConfig describes:
// resize to the input size, channel order, scale, mean/std, forward, per-pixel argmax over the
// class scores, labels back at the frame size (nearest neighbour).
class SemanticSegmenter {
 public:
  // Throws util::Error naming the model file when OpenCV cannot load it.
  SemanticSegmenter(ModelConfig config, const std::filesystem::path& model_file);

  // bgr: CV_8UC3. Not thread-safe (the network keeps state): one segmenter per thread.
  SemanticMasks segment(const cv::Mat& bgr);

  // One pass over a blank input. OpenCV sets the network's layers up on its first pass, which
  // takes about 1.6 times as long as later ones: a live pipeline pays it here, at setup, rather
  // than on the first frame, which waits for its mask.
  void warmUp();

  [[nodiscard]] const ModelConfig& config() const { return config_; }

 private:
  [[nodiscard]] cv::Mat inputBlob(const cv::Mat& bgr) const;
  [[nodiscard]] cv::Mat labelsFromScores(const cv::Mat& scores) const;

  ModelConfig config_;
  std::vector<int> dynamic_indices_;
  FastDnnLayers fast_layers_;  // before net_: the net is built with them
  cv::dnn::Net net_;
};

}  // namespace segslam::segmentation
