#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

#include "segslam/feature/orb_pattern.h"

namespace segslam::feature {

// The descriptor's binary tests compare single pixels, which noise flips easily; they are taken on
// the level image smoothed by a 7 x 7 Gaussian (sigma 2), as in ORB. `smoothed` is reused.
void smoothForDescriptor(const cv::Mat& level_image, cv::Mat& smoothed);

// Steered BRIEF (Rublee et al. 2011): the binary tests of a pattern, rotated by the keypoint's
// angle, on the smoothed image. Holds the pattern as float coordinate arrays so that rotating all
// 512 test points, the bulk of the work, is a vectorisable loop.
class SteeredBrief {
 public:
  explicit SteeredBrief(const OrbPattern& pattern);

  // Writes 32 bytes for the keypoint at `center` (level pixels, at least kPatternRadius from the
  // border of `smoothed`, CV_8UC1) with angle `angle_degrees` (as cv::KeyPoint::angle): test i is
  // bit i % 8 of byte i / 8, set when intensity(first) < intensity(second) at the points given
  // by steerPatternPoint.
  void compute(const cv::Mat& smoothed, cv::Point center, float angle_degrees,
               std::uint8_t* descriptor) const;

 private:
  static constexpr int kPoints = 2 * kDescriptorBits;
  // Point 2i is test i's first point, 2i + 1 its second.
  alignas(16) std::array<float, kPoints> x_{};
  alignas(16) std::array<float, kPoints> y_{};
};

}  // namespace segslam::feature
