#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "segslam/core/semantic_class.h"

namespace segslam::segmentation {

// The object label (core::SemanticClass) a network's class name stands for: a name that is a
// SemanticClass name is that class; Pascal VOC's indoor names are aliases (tvmonitor -> monitor,
// diningtable -> table, pottedplant -> plant); every other name (background, aeroplane, cow...)
// is kNone, so its pixels join no object.
core::SemanticClass semanticClassOfModelClass(std::string_view name);

// Translates a network's per-pixel class indices (ModelConfig::classes) into core::SemanticClass
// ids, the labels the map and the datasets use.
class SemanticClassMap {
 public:
  explicit SemanticClassMap(const std::vector<std::string>& model_classes);

  // model_labels: CV_8UC1 class indices; indices past the class list become kNone.
  [[nodiscard]] cv::Mat apply(const cv::Mat& model_labels) const;
  [[nodiscard]] core::SemanticClass classOf(int model_index) const;

 private:
  cv::Mat table_;  // 1 x 256 CV_8UC1: SemanticClass id per class index
};

}  // namespace segslam::segmentation
