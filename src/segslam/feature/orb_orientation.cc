#include "segslam/feature/orb_orientation.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

namespace segslam::feature {
namespace {

// kDiscHalfWidth[|dy|]: largest dx with dx^2 + dy^2 <= radius^2, i.e. the disc's row extents.
constexpr std::array<int, kOrientationRadius + 1> discHalfWidths() {
  std::array<int, kOrientationRadius + 1> half_widths{};
  for (int dy = 0; dy <= kOrientationRadius; ++dy) {
    int dx = 0;
    while ((dx + 1) * (dx + 1) + dy * dy <= kOrientationRadius * kOrientationRadius) ++dx;
    half_widths[dy] = dx;
  }
  return half_widths;
}

constexpr std::array<int, kOrientationRadius + 1> kDiscHalfWidth = discHalfWidths();

}  // namespace

float intensityCentroidAngle(const cv::Mat& image, cv::Point center) {
  CV_DbgAssert(image.type() == CV_8UC1);
  const std::uint8_t* middle = image.ptr<std::uint8_t>(center.y) + center.x;
  const auto step = static_cast<std::ptrdiff_t>(image.step1());
  int m10 = 0;
  for (int dx = -kDiscHalfWidth[0]; dx <= kDiscHalfWidth[0]; ++dx) m10 += dx * middle[dx];
  // Rows +dy and -dy together: their sum weighs m10, their difference m01.
  int m01 = 0;
  for (int dy = 1; dy <= kOrientationRadius; ++dy) {
    const std::uint8_t* below = middle + dy * step;
    const std::uint8_t* above = middle - dy * step;
    int row_difference = 0;
    for (int dx = -kDiscHalfWidth[dy]; dx <= kDiscHalfWidth[dy]; ++dx) {
      m10 += dx * (below[dx] + above[dx]);
      row_difference += below[dx] - above[dx];
    }
    m01 += dy * row_difference;
  }
  float degrees = static_cast<float>(
      std::atan2(static_cast<double>(m01), static_cast<double>(m10)) * (180.0 / std::numbers::pi));
  if (degrees < 0.0f) degrees += 360.0f;
  if (degrees >= 360.0f) degrees -= 360.0f;
  return degrees;
}

}  // namespace segslam::feature
