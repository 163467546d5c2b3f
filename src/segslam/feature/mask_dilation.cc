#include "segslam/feature/mask_dilation.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace segslam::feature {

namespace {

// Each pixel's distance along its row to the nearest set pixel, capped at `cap` (<= 255).
cv::Mat rowDistances(const cv::Mat& mask, int cap) {
  cv::Mat distances(mask.size(), CV_8UC1);
  for (int y = 0; y < mask.rows; ++y) {
    const auto* set = mask.ptr<std::uint8_t>(y);
    auto* distance = distances.ptr<std::uint8_t>(y);
    int run = cap;
    for (int x = 0; x < mask.cols; ++x) {
      run = set[x] != 0 ? 0 : std::min(run + 1, cap);
      distance[x] = static_cast<std::uint8_t>(run);
    }
    run = cap;
    for (int x = mask.cols - 1; x >= 0; --x) {
      run = set[x] != 0 ? 0 : std::min(run + 1, cap);
      distance[x] = std::min(distance[x], static_cast<std::uint8_t>(run));
    }
  }
  return distances;
}

// out[x] = 255 where distance[x] <= limit; left as it is elsewhere.
void markWithin(const std::uint8_t* distance, std::uint8_t limit, std::uint8_t* out, int cols) {
  int x = 0;
#if CV_SIMD
  const cv::v_uint8 limits = cv::vx_setall_u8(limit);
  for (; x <= cols - cv::v_uint8::nlanes; x += cv::v_uint8::nlanes) {
    cv::v_store(out + x, cv::vx_load(out + x) | (cv::vx_load(distance + x) <= limits));
  }
#endif
  for (; x < cols; ++x) {
    if (distance[x] <= limit) out[x] = 255;
  }
}

}  // namespace

RowHalfWidths discHalfWidths(int radius) {
  RowHalfWidths half_widths;
  for (int dy = -radius; dy <= radius; ++dy) {
    int dx = 0;
    while ((dx + 1) * (dx + 1) + dy * dy <= radius * radius) ++dx;
    half_widths.push_back(dx);
  }
  return half_widths;
}

RowHalfWidths ellipseHalfWidths(int radius) {
  const cv::Mat element =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
  RowHalfWidths half_widths;
  for (int row = 0; row < element.rows; ++row) {
    half_widths.push_back((cv::countNonZero(element.row(row)) - 1) / 2);
  }
  return half_widths;
}

cv::Mat dilateByRows(const cv::Mat& mask, const RowHalfWidths& half_widths) {
  cv::Mat dilated(mask.size(), CV_8UC1);
  dilateByRows(mask, half_widths, dilated);
  return dilated;
}

void dilateByRows(const cv::Mat& mask, const RowHalfWidths& half_widths, cv::Mat& dilated) {
  if (mask.type() != CV_8UC1 || half_widths.size() % 2 == 0) {
    throw std::invalid_argument("dilateByRows: a CV_8UC1 mask and an odd number of rows");
  }
  if (dilated.type() != CV_8UC1 || dilated.size() != mask.size()) {
    throw std::invalid_argument("dilateByRows: the output must be CV_8UC1 of the mask's size");
  }
  const int radius = static_cast<int>(half_widths.size()) / 2;
  const int widest = *std::max_element(half_widths.begin(), half_widths.end());
  if (widest > 254) throw std::invalid_argument("dilateByRows: rows at most 254 pixels wide");
  const cv::Mat distances = rowDistances(mask, widest + 1);
  dilated.setTo(0);
  for (int y = 0; y < mask.rows; ++y) {
    auto* out = dilated.ptr<std::uint8_t>(y);
    for (int dy = std::max(-radius, -y); dy <= std::min(radius, mask.rows - 1 - y); ++dy) {
      markWithin(distances.ptr<std::uint8_t>(y + dy),
                 static_cast<std::uint8_t>(half_widths[dy + radius]), out, mask.cols);
    }
  }
}

}  // namespace segslam::feature
