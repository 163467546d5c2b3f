#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

#include "segslam/feature/descriptor_distance.h"

namespace segslam::feature {

// Test points lie within this radius of the keypoint, so that they stay inside the patch (and
// inside the detection border) whatever the keypoint's orientation.
inline constexpr int kPatternRadius = 15;

// An offset from the keypoint, in level pixels, in the keypoint's own frame (x along its angle).
struct PatternPoint {
  std::int8_t x = 0;
  std::int8_t y = 0;
};

// One binary test of the descriptor: bit = intensity(first) < intensity(second).
struct BinaryTest {
  PatternPoint first;
  PatternPoint second;
};

using OrbPattern = std::array<BinaryTest, kDescriptorBits>;

// The 256 tests our descriptors use, learned on TUM frames with tools/learn_orb_pattern.cc (see
// docs/orb_pattern.md); the table itself is the generated orb_pattern_table.cc.
const OrbPattern& learnedOrbPattern();

// Rounds to the nearest integer, ties to even (as cvRound), in plain float arithmetic so that
// loops over it vectorise: adding 1.5 * 2^23 pushes the fraction out of the mantissa, where the
// FPU rounds it away. Exact for |value| < 2^22 under IEEE float semantics (-ffast-math would
// fold the two additions away).
inline float roundHalfEven(float value) {
  constexpr float kShift = 12582912.0f;
  return (value + kShift) - kShift;
}

// Where a pattern point falls in the image for a keypoint rotated by angle (cos_angle, sin_angle),
// rounded to the nearest pixel. The descriptor (SteeredBrief) computes exactly this, and pattern
// learning goes through here, so the tests are learned just as they are evaluated.
inline cv::Point steerPatternPoint(PatternPoint point, float cos_angle, float sin_angle) {
  const float x = static_cast<float>(point.x);
  const float y = static_cast<float>(point.y);
  return {static_cast<int>(roundHalfEven(x * cos_angle - y * sin_angle)),
          static_cast<int>(roundHalfEven(x * sin_angle + y * cos_angle))};
}

}  // namespace segslam::feature
