#pragma once

#include <cstddef>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "segslam/place/cnn_feature_extractor.h"
#include "segslam/place/place_descriptor_method.h"

namespace segslam::place {

// What is kept of one image: every layer's feature map area-averaged to at most the config's
// stored_grid (float16, C rows x cells), and the static mask at a small fixed size.
struct CnnImageFeatures {
  std::vector<cv::Mat> layers;  // CV_16FC1, channels x (grid width * grid height)
  cv::Mat static_mask;          // CV_8UC1 of CnnFeatureBank::kMaskSize; empty = all static
};

// The features of every image added, shared by the methods of one backbone so that the network
// runs once per image however many layers and variants are compared.
class CnnFeatureBank {
 public:
  // Masks are kept at this size: fine enough for the erosion of the pooled descriptor.
  static constexpr int kMaskWidth = 160;
  static constexpr int kMaskHeight = 120;

  // Runs the network once on a blank image to learn each layer's grid.
  explicit CnnFeatureBank(CnnFeatureExtractor extractor);

  // Makes image `index` available: extracts it when index == size(); when another method
  // already added it (index < size()), `image` must be that same image.
  void add(std::size_t index, const PlaceImage& image);

  // Frees image `index`'s features: it must never be compared again. Indices are not reused.
  void release(std::size_t index);
  // Image `index`'s features as bytes (for a map file), with the backbone's and layers' names.
  [[nodiscard]] std::string encodeImage(std::size_t index) const;
  // Adds features that encodeImage() wrote as image `index` (== size()) instead of extracting
  // them; false, and nothing added, when they come from another backbone, layer or grid.
  bool addEncoded(std::size_t index, std::string_view bytes);

  [[nodiscard]] std::size_t size() const { return images_.size(); }
  [[nodiscard]] const CnnImageFeatures& image(std::size_t i) const { return images_.at(i); }
  [[nodiscard]] const CnnBackboneConfig& config() const { return extractor_.config(); }
  // Stored grid of each layer (1 x 1 for layers without a spatial extent).
  [[nodiscard]] const std::vector<cv::Size>& grids() const { return grids_; }
  [[nodiscard]] const std::vector<int>& channels() const { return channels_; }
  [[nodiscard]] std::size_t bytesPerImage() const;
  // Wall time, and processor time of all the process's threads: on a machine shared with other
  // work the latter tells what the extraction costs.
  [[nodiscard]] double meanExtractionMilliseconds() const;
  [[nodiscard]] double meanExtractionCpuMilliseconds() const;

 private:
  CnnImageFeatures compute(const PlaceImage& image);

  CnnFeatureExtractor extractor_;
  std::vector<cv::Size> grids_;
  std::vector<int> channels_;
  std::vector<CnnImageFeatures> images_;
  std::vector<const unsigned char*> sources_;  // pixels each image was computed from
  std::size_t extracted_ = 0;                  // images the network ran on (not added from bytes)
  double extraction_ms_ = 0.0;
  double extraction_cpu_ms_ = 0.0;
};

enum class CnnVariant {
  // The method's equation 1: the union mask resized to the layer's grid, multiplied over the
  // channels into both flattened maps, compared by cosine similarity.
  kFlattened,
  // Masked average pooling: per cell of the pooling grid, the feature map averaged over the
  // union static area eroded by the layer's erosion_px (normalised by that area), so moving
  // objects and the features that see them drop out instead of zeroing part of the vector.
  kPooled,
  // Masked average pooling with each map averaged over its own image's static area (eroded the
  // same way) instead of the union: what the other image's moving objects hide stays in this
  // one (the lesson of the bag of words, place::BowMasking::kOwnStaticArea).
  kPooledOwnStaticArea,
};

// One layer of a backbone compared one way; named "cnn:<layer>" (flattened),
// "cnn:<layer>:pooled" or "cnn:<layer>:pooled:static".
class CnnPlaceMethod : public PlaceDescriptorMethod {
 public:
  CnnPlaceMethod(std::shared_ptr<CnnFeatureBank> bank, std::size_t layer, CnnVariant variant);

  [[nodiscard]] std::string name() const override;
  void add(const PlaceImage& image) override;
  [[nodiscard]] std::size_t size() const override { return count_; }
  [[nodiscard]] double similarity(std::size_t i, std::size_t j, bool union_mask) const override;
  // The next image from CnnFeatureBank::encodeImage()'s bytes; false (nothing added) when they do
  // not fit the bank's backbone.
  bool addEncoded(std::string_view bytes);

 private:
  // Static share of each cell of the layer's grid (1 x cells), the mask eroded by the layer's
  // erosion_px; an empty mask is all static.
  [[nodiscard]] cv::Mat poolingWeights(const cv::Mat& static_mask) const;

  std::shared_ptr<CnnFeatureBank> bank_;
  std::size_t layer_;
  CnnVariant variant_;
  std::size_t count_ = 0;
};

// Every layer of the bank's backbone, flattened and (for layers with a spatial extent) pooled.
std::vector<std::unique_ptr<PlaceDescriptorMethod>> makeCnnPlaceMethods(
    const std::shared_ptr<CnnFeatureBank>& bank);

}  // namespace segslam::place
