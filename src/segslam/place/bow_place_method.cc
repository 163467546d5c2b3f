#include "segslam/place/bow_place_method.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>

namespace segslam::place {

namespace {

bool isStaticAt(const cv::Mat& static_mask, const cv::Point2f& point) {
  if (static_mask.empty()) return true;
  const int x = std::clamp(cvRound(point.x), 0, static_mask.cols - 1);
  const int y = std::clamp(cvRound(point.y), 0, static_mask.rows - 1);
  return static_mask.at<std::uint8_t>(y, x) != 0;
}

}  // namespace

BowPlaceMethod::BowPlaceMethod(std::shared_ptr<const Vocabulary> vocabulary,
                               const feature::OrbExtractorOptions& orb_options, BowMasking masking)
    : vocabulary_(std::move(vocabulary)), extractor_(orb_options), masking_(masking) {
  if (!vocabulary_) throw std::invalid_argument("BowPlaceMethod: no vocabulary");
}

std::string BowPlaceMethod::name() const {
  return masking_ == BowMasking::kOwnStaticArea ? "bow:static" : "bow";
}

void BowPlaceMethod::add(const PlaceImage& image) {
  if (image.bgr.empty() || image.bgr.type() != CV_8UC3) {
    throw std::invalid_argument("BowPlaceMethod: the image must be a non-empty CV_8UC3");
  }
  const cv::Mat& mask = image.static_mask;
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != image.bgr.size())) {
    throw std::invalid_argument("BowPlaceMethod: the mask must be CV_8UC1 of the image's size");
  }
  cv::Mat gray;
  cv::cvtColor(image.bgr, gray, cv::COLOR_BGR2GRAY);
  ImageWords words;
  extractor_.extract(gray, cv::Mat(), words.keypoints, words.descriptors);
  // An all-static mask is dropped: it changes nothing and costs a full image per entry.
  if (!mask.empty() && cv::countNonZero(mask) < mask.rows * mask.cols) {
    words.static_mask = mask.clone();
  }
  words.bow = vocabulary_->transform(words.descriptors);
  if (masking_ == BowMasking::kOwnStaticArea && !words.static_mask.empty()) {
    std::vector<cv::KeyPoint> static_keypoints;
    cv::Mat static_descriptors;
    extractor_.extract(gray, 255 - words.static_mask, static_keypoints, static_descriptors);
    words.static_bow = vocabulary_->transform(static_descriptors);
  }
  images_.push_back(std::move(words));
}

BowVector BowPlaceMethod::staticWords(const ImageWords& image, const ImageWords& other) const {
  cv::Mat kept;
  for (std::size_t k = 0; k < image.keypoints.size(); ++k) {
    const cv::Point2f& point = image.keypoints[k].pt;
    if (isStaticAt(image.static_mask, point) && isStaticAt(other.static_mask, point)) {
      kept.push_back(image.descriptors.row(static_cast<int>(k)));
    }
  }
  return vocabulary_->transform(kept);
}

double BowPlaceMethod::similarity(std::size_t i, std::size_t j, bool union_mask) const {
  const ImageWords& a = images_.at(i);
  const ImageWords& b = images_.at(j);
  if (!union_mask || (a.static_mask.empty() && b.static_mask.empty())) {
    return l1Score(a.bow, b.bow);
  }
  if (masking_ == BowMasking::kOwnStaticArea) {
    return l1Score(a.static_mask.empty() ? a.bow : a.static_bow,
                   b.static_mask.empty() ? b.bow : b.static_bow);
  }
  return l1Score(staticWords(a, b), staticWords(b, a));
}

}  // namespace segslam::place
