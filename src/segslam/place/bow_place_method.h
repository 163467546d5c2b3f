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

// How the bag of words uses the images' static masks when compared with masks.
enum class BowMasking {
  // "bow", the method's variant: ORB on the whole image; both images' vectors are rebuilt from
  // the keypoints on pixels static in both images (the union mask).
  kUnionOfKeypoints,
  // "bow:static": each image's ORB keypoints are extracted on its own static area, so that the
  // whole feature budget goes to what is static, and the two vectors are compared as they are.
  // The other image's mask removes nothing: the views of a loop are not pixel-aligned (up to
  // 0.3 m and 20 deg apart), so its moving objects hide other static words in this image than
  // the ones at the same pixels, and dropping those costs loops more than other pairs.
  kOwnStaticArea,
};

// Bag-of-words place descriptor: ORB, words of our vocabulary tree, l1Score. Without masks both
// variants describe the whole image.
class BowPlaceMethod : public PlaceDescriptorMethod {
 public:
  explicit BowPlaceMethod(std::shared_ptr<const Vocabulary> vocabulary,
                          const feature::OrbExtractorOptions& orb_options = {},
                          BowMasking masking = BowMasking::kUnionOfKeypoints);

  [[nodiscard]] std::string name() const override;
  // Throws std::invalid_argument for an empty image or a mask of another size or type.
  void add(const PlaceImage& image) override;
  [[nodiscard]] std::size_t size() const override { return images_.size(); }
  // Throws std::out_of_range for an index >= size().
  [[nodiscard]] double similarity(std::size_t i, std::size_t j, bool union_mask) const override;

  // The whole image's vector.
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
    // kOwnStaticArea: the vector of the keypoints extracted on the static area; empty when the
    // whole image is static (bow stands for it).
    BowVector static_bow;
  };

  // The words of `image`'s keypoints that are static in both masks.
  [[nodiscard]] BowVector staticWords(const ImageWords& image, const ImageWords& other) const;

  std::shared_ptr<const Vocabulary> vocabulary_;
  feature::OrbExtractor extractor_;
  BowMasking masking_;
  std::vector<ImageWords> images_;
};

}  // namespace segslam::place
