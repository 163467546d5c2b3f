#include "segslam/feature/descriptor_matcher.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "segslam/feature/descriptor_distance.h"

namespace segslam::feature {
namespace {

void requireDescriptors(const cv::Mat& descriptors, const char* name) {
  if (descriptors.empty()) return;
  if (descriptors.type() != CV_8UC1 || descriptors.cols != kDescriptorBytes) {
    throw std::invalid_argument(std::string("matchDescriptors: ") + name +
                                " descriptors must be N x 32 CV_8UC1");
  }
}

struct NearestTwo {
  int best_index = -1;
  int best = std::numeric_limits<int>::max();
  int second = std::numeric_limits<int>::max();
};

NearestTwo findNearestTwo(const std::uint8_t* query, const cv::Mat& train) {
  NearestTwo nearest;
  for (int row = 0; row < train.rows; ++row) {
    const int distance = descriptorDistance(query, train.ptr<std::uint8_t>(row));
    if (distance < nearest.best) {
      nearest.second = nearest.best;
      nearest.best = distance;
      nearest.best_index = row;
    } else if (distance < nearest.second) {
      nearest.second = distance;
    }
  }
  return nearest;
}

bool passesRatioTest(const NearestTwo& nearest, double ratio) {
  if (nearest.second == std::numeric_limits<int>::max()) return true;  // a single candidate
  return nearest.best < ratio * nearest.second;
}

}  // namespace

std::vector<cv::DMatch> matchDescriptors(const cv::Mat& query, const cv::Mat& train,
                                         const DescriptorMatcherOptions& options) {
  requireDescriptors(query, "query");
  requireDescriptors(train, "train");
  std::vector<cv::DMatch> matches;
  if (query.empty() || train.empty()) return matches;
  for (int row = 0; row < query.rows; ++row) {
    const NearestTwo nearest = findNearestTwo(query.ptr<std::uint8_t>(row), train);
    if (nearest.best > options.max_distance) continue;
    if (options.ratio < 1.0 && !passesRatioTest(nearest, options.ratio)) continue;
    matches.emplace_back(row, nearest.best_index, static_cast<float>(nearest.best));
  }
  return matches;
}

}  // namespace segslam::feature
