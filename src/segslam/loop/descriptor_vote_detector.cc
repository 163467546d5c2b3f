#include "segslam/loop/descriptor_vote_detector.h"

#include <algorithm>
#include <numeric>

#include "segslam/feature/descriptor_distance.h"

namespace segslam::loop {

DescriptorVoteDetector::DescriptorVoteDetector(DescriptorVoteOptions options) : options_(options) {}

DescriptorVoteDetector::Signature DescriptorVoteDetector::signatureOf(
    const map::KeyFrame& keyframe) const {
  std::vector<std::size_t> order(keyframe.keypoints.size());
  std::iota(order.begin(), order.end(), 0);
  const std::size_t kept =
      std::min(order.size(), static_cast<std::size_t>(options_.signature_size));
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(kept), order.end(),
                    [&](std::size_t a, std::size_t b) {
                      return keyframe.keypoints[a].response > keyframe.keypoints[b].response;
                    });
  Signature signature;
  signature.keyframe_id = keyframe.id;
  signature.descriptors.create(static_cast<int>(kept), feature::kDescriptorBytes, CV_8U);
  for (std::size_t k = 0; k < kept; ++k) {
    keyframe.descriptors.row(static_cast<int>(order[k]))
        .copyTo(signature.descriptors.row(static_cast<int>(k)));
    signature.pixels.push_back(keyframe.keypoints[order[k]].pt);
  }
  signature.dynamic_mask = keyframe.dynamic_mask;
  return signature;
}

double DescriptorVoteDetector::score(const Signature& a, const Signature& b) const {
  std::vector<const std::uint8_t*> b_rows;
  for (int j = 0; j < b.descriptors.rows; ++j) {
    if (!a.dynamic_mask.at(b.pixels[static_cast<std::size_t>(j)])) {
      b_rows.push_back(b.descriptors.ptr<std::uint8_t>(j));
    }
  }
  int voters = 0;
  int votes = 0;
  for (int i = 0; i < a.descriptors.rows; ++i) {
    if (b.dynamic_mask.at(a.pixels[static_cast<std::size_t>(i)])) continue;
    ++voters;
    const std::uint8_t* row = a.descriptors.ptr<std::uint8_t>(i);
    int best = 256;
    int second = 256;
    for (const std::uint8_t* other : b_rows) {
      const int d = feature::descriptorDistance(row, other);
      if (d < best) {
        second = best;
        best = d;
      } else if (d < second) {
        second = d;
      }
    }
    if (best <= options_.max_distance && best < options_.ratio * second) ++votes;
  }
  return voters == 0 ? 0.0 : static_cast<double>(votes) / voters;
}

void DescriptorVoteDetector::add(const map::KeyFrame& keyframe) {
  signatures_.push_back(signatureOf(keyframe));
}

void DescriptorVoteDetector::forget(std::uint64_t keyframe_id) {
  std::erase_if(signatures_,
                [keyframe_id](const Signature& s) { return s.keyframe_id == keyframe_id; });
}

std::vector<std::uint64_t> DescriptorVoteDetector::candidates(
    const map::KeyFrame& query, const std::set<std::uint64_t>& covisible,
    std::size_t max_candidates) const {
  const Signature query_signature = signatureOf(query);
  double threshold = 1.0;
  bool any_covisible = false;
  std::vector<std::pair<double, std::uint64_t>> scored;
  for (const Signature& signature : signatures_) {
    if (signature.keyframe_id == query.id) continue;
    const double s = score(query_signature, signature);
    if (covisible.contains(signature.keyframe_id)) {
      threshold = std::min(threshold, s);
      any_covisible = true;
    } else {
      scored.emplace_back(s, signature.keyframe_id);
    }
  }
  threshold = std::max(any_covisible ? threshold : 0.0, options_.min_score);
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::uint64_t> result;
  for (const auto& [s, id] : scored) {
    if (result.size() >= max_candidates || s < threshold) break;
    if (s < options_.min_relative_score * scored.front().first) break;
    result.push_back(id);
  }
  return result;
}

}  // namespace segslam::loop
