#include "segslam/feature/orb_descriptor.h"

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

namespace segslam::feature {

void smoothForDescriptor(const cv::Mat& level_image, cv::Mat& smoothed) {
  cv::GaussianBlur(level_image, smoothed, cv::Size(7, 7), 2.0, 2.0, cv::BORDER_REFLECT_101);
}

SteeredBrief::SteeredBrief(const OrbPattern& pattern) {
  for (int test = 0; test < kDescriptorBits; ++test) {
    x_[2 * test] = pattern[test].first.x;
    y_[2 * test] = pattern[test].first.y;
    x_[2 * test + 1] = pattern[test].second.x;
    y_[2 * test + 1] = pattern[test].second.y;
  }
}

void SteeredBrief::compute(const cv::Mat& smoothed, cv::Point center, float angle_degrees,
                           std::uint8_t* descriptor) const {
  CV_DbgAssert(smoothed.type() == CV_8UC1);
  const double radians = angle_degrees * (std::numbers::pi / 180.0);
  const auto cos_angle = static_cast<float>(std::cos(radians));
  const auto sin_angle = static_cast<float>(std::sin(radians));
  const auto step = static_cast<float>(smoothed.step1());
  // Same arithmetic as steerPatternPoint, turned into a byte offset from the centre. The offset
  // is exact in float: |offset| <= 16 * step + 16, far below 2^24.
  alignas(16) std::array<int, kPoints> offsets;
  for (int i = 0; i < kPoints; ++i) {
    const float x = roundHalfEven(x_[i] * cos_angle - y_[i] * sin_angle);
    const float y = roundHalfEven(x_[i] * sin_angle + y_[i] * cos_angle);
    offsets[i] = static_cast<int>(y * step + x);
  }
  const std::uint8_t* middle = smoothed.ptr<std::uint8_t>(center.y) + center.x;
  for (int byte = 0; byte < kDescriptorBytes; ++byte) {
    const int* pair = &offsets[16 * byte];
    unsigned bits = 0;
    for (int bit = 0; bit < 8; ++bit) {
      bits |= static_cast<unsigned>(middle[pair[2 * bit]] < middle[pair[2 * bit + 1]]) << bit;
    }
    descriptor[byte] = static_cast<std::uint8_t>(bits);
  }
}

}  // namespace segslam::feature
