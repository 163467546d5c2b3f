#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace segslam::feature {

struct DescriptorMatcherOptions {
  // Matches farther apart than this (Hamming bits out of 256) are dropped.
  int max_distance = 64;
  // Lowe's ratio test: the best distance must be below ratio x the second best (an ambiguous
  // match, e.g. on repeated texture, is worse than none). 1.0 disables the test.
  double ratio = 0.8;
};

// Brute-force matching of binary descriptors (N x 32 CV_8U rows): for each query row, the train row
// at the smallest Hamming distance, if it passes the ratio test and the distance limit. Matches
// come in query order; distance is in bits. Throws std::invalid_argument on a wrong descriptor
// layout.
std::vector<cv::DMatch> matchDescriptors(const cv::Mat& query, const cv::Mat& train,
                                         const DescriptorMatcherOptions& options = {});

}  // namespace segslam::feature
