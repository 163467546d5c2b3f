#pragma once

#include <cstddef>
#include <opencv2/core.hpp>
#include <string>

namespace segslam::place {

// One image of a place-recognition experiment or of the loop detector's database.
struct PlaceImage {
  cv::Mat bgr;          // CV_8UC3
  cv::Mat static_mask;  // CV_8UC1, 255 = static, 0 = dynamic; empty = everything static
};

// A way of scoring how similar two places look (bag of words, one CNN layer, ...). Images are
// added once and referred to by the order of addition, so that methods can keep whatever compact
// per-image data they need (words, pooled feature maps) instead of the images.
class PlaceDescriptorMethod {
 public:
  virtual ~PlaceDescriptorMethod() = default;

  // Short name for tables and plots, e.g. "bow" or "cnn:pool3".
  [[nodiscard]] virtual std::string name() const = 0;
  virtual void add(const PlaceImage& image) = 0;
  [[nodiscard]] virtual std::size_t size() const = 0;
  // Higher is more similar. With union_mask, only what is static in both images is compared.
  [[nodiscard]] virtual double similarity(std::size_t i, std::size_t j, bool union_mask) const = 0;
};

}  // namespace segslam::place
