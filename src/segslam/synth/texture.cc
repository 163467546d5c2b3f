#include "segslam/synth/texture.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace segslam::synth {

namespace {

constexpr int kMaxLevels = 10;

// Piecewise-linear log2, exact at powers of two and monotonic: enough to pick mip levels, and much
// cheaper than std::log2 in the per-pixel path.
float fastLog2(float x) {
  const auto bits = std::bit_cast<std::uint32_t>(x);
  const int exponent = static_cast<int>((bits >> 23) & 0xffu) - 127;
  const float mantissa = static_cast<float>(bits & 0x7fffffu) / 8388608.0f;
  return static_cast<float>(exponent) + mantissa;
}

}  // namespace

Texture::Texture(const cv::Mat& image, double texel_size) : texel_size_(texel_size) {
  if (image.type() != CV_8UC3 || image.empty() || !(texel_size > 0.0)) {
    throw std::invalid_argument("Texture needs a non-empty CV_8UC3 image and a positive texel");
  }
  levels_.push_back(image.clone());
  while (static_cast<int>(levels_.size()) < kMaxLevels && levels_.back().cols >= 2 &&
         levels_.back().rows >= 2) {
    cv::Mat smaller;
    cv::pyrDown(levels_.back(), smaller);
    levels_.push_back(smaller);
  }
  for (int level = 0; level < levelCount(); ++level) {
    texels_per_metre_.push_back(std::ldexp(1.0 / texel_size_, -level));
  }
}

Eigen::Vector3f Texture::sample(double s, double t, double footprint) const {
  const auto texels = static_cast<float>(footprint * texels_per_metre_[0]);
  const float lod = texels > 1.0f ? fastLog2(texels) : 0.0f;
  const int last = levelCount() - 1;
  const int lower = std::min(static_cast<int>(lod), last);
  // Blend two levels only near the switch from one to the next ("brilinear" filtering): as smooth
  // to the eye as full trilinear filtering at a little more than half of its cost.
  const float blend = std::clamp((lod - static_cast<float>(lower) - 0.3f) * 2.5f, 0.0f, 1.0f);
  const auto at_level = [&](int level) {
    const double scale = texels_per_metre_[level];
    return bilinear(level, s * scale - 0.5, t * scale - 0.5);
  };
  if (lower == last || blend <= 0.0f) return at_level(lower);
  if (blend >= 1.0f) return at_level(lower + 1);
  return (1.0f - blend) * at_level(lower) + blend * at_level(lower + 1);
}

Eigen::Vector3f Texture::bilinear(int level, double x, double y) const {
  const cv::Mat& image = levels_[level];
  x = std::clamp(x, 0.0, static_cast<double>(image.cols - 1));
  y = std::clamp(y, 0.0, static_cast<double>(image.rows - 1));
  const int x0 = static_cast<int>(x);
  const int y0 = static_cast<int>(y);
  const int step_x = x0 + 1 < image.cols ? 3 : 0;
  const int y1 = std::min(y0 + 1, image.rows - 1);
  const auto fx = static_cast<float>(x - x0);
  const auto fy = static_cast<float>(y - y0);
  const float w00 = (1.0f - fx) * (1.0f - fy);
  const float w01 = fx * (1.0f - fy);
  const float w10 = (1.0f - fx) * fy;
  const float w11 = fx * fy;
  const std::uint8_t* top = image.ptr<std::uint8_t>(y0) + 3 * x0;
  const std::uint8_t* bottom = image.ptr<std::uint8_t>(y1) + 3 * x0;
  Eigen::Vector3f colour;
  for (int c = 0; c < 3; ++c) {
    colour[c] = w00 * top[c] + w01 * top[c + step_x] + w10 * bottom[c] + w11 * bottom[c + step_x];
  }
  return colour;
}

}  // namespace segslam::synth
