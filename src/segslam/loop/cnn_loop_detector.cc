#include "segslam/loop/cnn_loop_detector.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "segslam/util/error.h"

namespace segslam::loop {

namespace {

// The config reduced to the compared layer: the network then stops at that layer.
place::CnnBackboneConfig withOnlyLayer(place::CnnBackboneConfig config, const std::string& layer,
                                       const std::filesystem::path& config_file) {
  const auto it = std::find_if(config.layers.begin(), config.layers.end(),
                               [&](const place::CnnLayer& l) { return l.name == layer; });
  if (it == config.layers.end()) {
    util::failAt(config_file, fmt::format("the backbone has no layer named '{}'", layer));
  }
  const place::CnnLayer kept = *it;
  config.layers = {kept};
  return config;
}

// The place module's static mask (255 = static) from a keyframe's dynamic one (non-zero).
cv::Mat staticMaskOf(const cv::Mat& dynamic_mask) {
  if (dynamic_mask.empty() || cv::countNonZero(dynamic_mask) == 0) return {};
  cv::Mat static_mask;
  cv::compare(dynamic_mask, 0, static_mask, cv::CMP_EQ);
  return static_mask;
}

}  // namespace

CnnLoopDetector::CnnLoopDetector(const CnnLoopBackbone& backbone, CnnLoopOptions options)
    : options_(std::move(options)),
      bank_(std::make_shared<place::CnnFeatureBank>(place::CnnFeatureExtractor(
          withOnlyLayer(backbone.config, options_.layer, backbone.config_file),
          backbone.model_file))),
      method_(std::make_unique<place::CnnPlaceMethod>(bank_, 0, place::CnnVariant::kPooled)) {}

void CnnLoopDetector::describe(const map::KeyFrame& keyframe) {
  if (index_of_keyframe_.contains(keyframe.id)) return;
  if (keyframe.image.empty()) {
    throw std::logic_error(
        fmt::format("CnnLoopDetector: keyframe {} has no image to describe", keyframe.id));
  }
  index_of_keyframe_[keyframe.id] = method_->size();
  method_->add({keyframe.image, staticMaskOf(keyframe.dynamic_mask.toMat())});
}

void CnnLoopDetector::add(const map::KeyFrame& keyframe) {
  describe(keyframe);  // done already when the loop closer called it
  candidates_[keyframe.id] = &keyframe;
}

void CnnLoopDetector::forget(std::uint64_t keyframe_id) {
  const auto it = index_of_keyframe_.find(keyframe_id);
  if (it == index_of_keyframe_.end()) return;
  bank_->release(it->second);
  index_of_keyframe_.erase(it);
  candidates_.erase(keyframe_id);
}

std::string CnnLoopDetector::savedDescription(std::uint64_t keyframe_id) const {
  const auto it = index_of_keyframe_.find(keyframe_id);
  return it == index_of_keyframe_.end() ? std::string() : bank_->encodeImage(it->second);
}

void CnnLoopDetector::addRestored(const map::KeyFrame& keyframe, const std::string& description) {
  const std::size_t index = method_->size();
  if (description.empty() || !method_->addEncoded(description)) return;
  index_of_keyframe_[keyframe.id] = index;
  candidates_[keyframe.id] = &keyframe;
}

std::size_t CnnLoopDetector::indexOf(std::uint64_t keyframe_id) const {
  const auto it = index_of_keyframe_.find(keyframe_id);
  if (it == index_of_keyframe_.end()) {
    throw std::logic_error(
        fmt::format("CnnLoopDetector: keyframe {} was not described", keyframe_id));
  }
  return it->second;
}

double CnnLoopDetector::similarity(std::uint64_t a, std::uint64_t b) const {
  return method_->similarity(indexOf(a), indexOf(b), /*union_mask=*/true);
}

std::vector<std::uint64_t> CnnLoopDetector::candidates(const map::KeyFrame& query,
                                                       const std::set<std::uint64_t>& covisible,
                                                       std::size_t max_candidates) const {
  const double threshold = covisibleScoreThreshold(
      query, covisible,
      [&](std::uint64_t id) -> std::optional<double> {
        if (!candidates_.contains(id)) return std::nullopt;
        return similarity(query.id, id);
      },
      options_.min_score, CovisibleScore::kMean);
  // Cosines of any two indoor views are close to 1: what a keyframe adds to its group's evidence
  // is its margin over the threshold, else many middling neighbours outweigh one true revisit.
  std::unordered_map<std::uint64_t, double> margins;
  for (const auto& [id, keyframe] : candidates_) {
    if (keyframe->bad || id == query.id || covisible.contains(id)) continue;
    const double score = similarity(query.id, id);
    if (score > threshold) margins[id] = score - threshold;
  }
  return bestCandidateGroups(
      margins, [&](std::uint64_t id) { return candidates_.at(id); }, options_.groups,
      max_candidates);
}

double CnnLoopDetector::meanExtractionMilliseconds() const {
  return bank_->meanExtractionMilliseconds();
}

double CnnLoopDetector::meanExtractionCpuMilliseconds() const {
  return bank_->meanExtractionCpuMilliseconds();
}

}  // namespace segslam::loop
