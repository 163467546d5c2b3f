#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "segslam/feature/orb_extractor.h"
#include "segslam/place/bow_vector.h"
#include "segslam/place/place_descriptor_method.h"
#include "segslam/place/vocabulary.h"

namespace segslam::place {

// Bag-of-words place descriptor ("bow"): ORB on the whole image, words of our vocabulary tree,
// l1Score. With the union mask, both images' vectors are rebuilt from the keypoints that lie on
// pixels static in both images, so that neither image's moving objects take part.
class BowPlaceMethod : public PlaceDescriptorMethod {
 public:
  explicit BowPlaceMethod(std::shared_ptr<const Vocabulary> vocabulary,
                          const feature::OrbExtractorOptions& orb_options = {});

  [[nodiscard]] std::string name() const override { return "bow"; }
  // Throws std::invalid_argument for an empty image or a mask of another size or type.
  void add(const PlaceImage& image) override;
  [[nodiscard]] std::size_t size() const override { return images_.size(); }
  // Throws std::out_of_range for an index >= size().
  [[nodiscard]] double similarity(std::size_t i, std::size_t j, bool union_mask) const override;

  [[nodiscard]] const BowVector& bowVector(std::size_t i) const { return images_.at(i).bow; }
  [[nodiscard]] const std::vector<cv::KeyPoint>& keypoints(std::size_t i) const {
    return images_.at(i).keypoints;
  }

 private:
  struct ImageWords {
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
    cv::Mat static_mask;  // empty when the whole image is static
    BowVector bow;
  };

  // The words of `image`'s keypoints that are static in both masks.
  [[nodiscard]] BowVector staticWords(const ImageWords& image, const ImageWords& other) const;

  std::shared_ptr<const Vocabulary> vocabulary_;
  feature::OrbExtractor extractor_;
  std::vector<ImageWords> images_;
};

}  // namespace segslam::place
