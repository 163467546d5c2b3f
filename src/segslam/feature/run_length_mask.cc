#include "segslam/feature/run_length_mask.h"

#include <algorithm>
#include <stdexcept>

namespace segslam::feature {

RunLengthMask::RunLengthMask(const cv::Mat& mask) {
  if (mask.empty()) return;
  if (mask.type() != CV_8UC1) {
    throw std::invalid_argument("RunLengthMask: mask must be CV_8UC1");
  }
  if (mask.cols > UINT16_MAX) throw std::invalid_argument("RunLengthMask: mask is too wide");
  size_ = mask.size();
  row_starts_.reserve(static_cast<std::size_t>(mask.rows) + 1);
  row_starts_.push_back(0);
  for (int row = 0; row < mask.rows; ++row) {
    const std::uint8_t* pixels = mask.ptr<std::uint8_t>(row);
    for (int col = 0; col < mask.cols;) {
      if (pixels[col] == 0) {
        ++col;
        continue;
      }
      const int begin = col;
      while (col < mask.cols && pixels[col] != 0) ++col;
      runs_.push_back({static_cast<std::uint16_t>(begin), static_cast<std::uint16_t>(col)});
    }
    row_starts_.push_back(static_cast<std::uint32_t>(runs_.size()));
  }
  if (runs_.empty()) *this = RunLengthMask();
  runs_.shrink_to_fit();
}

bool RunLengthMask::at(const cv::Point2f& pixel) const {
  if (empty()) return false;
  const int x = cvRound(pixel.x);
  const int y = cvRound(pixel.y);
  if (x < 0 || y < 0 || x >= size_.width || y >= size_.height) return false;
  const auto first = runs_.begin() + row_starts_[static_cast<std::size_t>(y)];
  const auto last = runs_.begin() + row_starts_[static_cast<std::size_t>(y) + 1];
  // The first run ending beyond x is the only one that can hold it.
  const auto run =
      std::upper_bound(first, last, x, [](int column, const Run& r) { return column < r.end; });
  return run != last && run->begin <= x;
}

cv::Mat RunLengthMask::toMat() const {
  if (empty()) return {};
  cv::Mat mask = cv::Mat::zeros(size_, CV_8UC1);
  for (int row = 0; row < size_.height; ++row) {
    std::uint8_t* pixels = mask.ptr<std::uint8_t>(row);
    for (std::uint32_t k = row_starts_[static_cast<std::size_t>(row)];
         k < row_starts_[static_cast<std::size_t>(row) + 1]; ++k) {
      std::fill(pixels + runs_[k].begin, pixels + runs_[k].end, std::uint8_t{255});
    }
  }
  return mask;
}

RunLengthMask RunLengthMask::united(const cv::Mat& other) const {
  if (other.empty()) return *this;
  if (empty()) return RunLengthMask(other);
  if (other.size() != size_) {
    throw std::invalid_argument("RunLengthMask::united: masks differ in size");
  }
  return RunLengthMask(toMat() | other);
}

}  // namespace segslam::feature
