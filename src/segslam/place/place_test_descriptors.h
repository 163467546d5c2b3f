#pragma once

// Synthetic descriptors for the place tests only (header-only, never linked into the library).

#include <cstdint>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

namespace segslam::place::testing {

inline void flipRandomBits(std::uint8_t* descriptor, int flips, std::mt19937& rng) {
  for (int i = 0; i < flips; ++i) {
    const auto bit = rng() % 256;
    descriptor[bit / 8] ^= static_cast<std::uint8_t>(1U << (bit % 8));
  }
}

inline cv::Mat randomDescriptors(int rows, std::uint32_t seed) {
  std::mt19937 rng(seed);
  cv::Mat descriptors(rows, 32, CV_8UC1);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < 32; ++c) descriptors.at<std::uint8_t>(r, c) = rng() & 0xFF;
  }
  return descriptors;
}

// Two-level clusters: `top` random prototypes (about 128 bits apart), each with `sub` variants
// 40 bits off it, each with `members` descriptors at most 3 bits off the variant. Returns one
// matrix per variant, so that variant v is "image" v.
inline std::vector<cv::Mat> clusteredDescriptorSets(int top, int sub, int members,
                                                    std::uint32_t seed) {
  std::mt19937 rng(seed);
  const cv::Mat prototypes = randomDescriptors(top, seed + 1);
  std::vector<cv::Mat> sets;
  for (int t = 0; t < top; ++t) {
    for (int s = 0; s < sub; ++s) {
      cv::Mat variant = prototypes.row(t).clone();
      flipRandomBits(variant.ptr<std::uint8_t>(), 40, rng);
      cv::Mat set(members, 32, CV_8UC1);
      for (int m = 0; m < members; ++m) {
        variant.copyTo(set.row(m));
        flipRandomBits(set.ptr<std::uint8_t>(m), static_cast<int>(rng() % 4), rng);
      }
      sets.push_back(set);
    }
  }
  return sets;
}

}  // namespace segslam::place::testing
