#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace segslam::feature {

// A binary image kept as the runs of set pixels on each row. A keyframe keeps its dynamic mask
// for as long as it lives (loop detection and late masks read it): a person over a 640x480 view
// takes a few kB this way instead of 300 kB.
class RunLengthMask {
 public:
  RunLengthMask() = default;
  // mask: empty (nothing set) or CV_8UC1, non-zero = set. Throws std::invalid_argument otherwise.
  explicit RunLengthMask(const cv::Mat& mask);

  // True when no pixel is set (as an empty dynamic mask: everything static).
  [[nodiscard]] bool empty() const { return runs_.empty(); }
  [[nodiscard]] cv::Size size() const { return size_; }
  // Whether the pixel nearest to `pixel` is set; false outside the image.
  [[nodiscard]] bool at(const cv::Point2f& pixel) const;
  // CV_8UC1, 255 where set; an empty Mat when nothing is set.
  [[nodiscard]] cv::Mat toMat() const;
  // Set where this mask or `other` (empty or CV_8UC1 of this mask's size) is.
  [[nodiscard]] RunLengthMask united(const cv::Mat& other) const;

 private:
  struct Run {
    std::uint16_t begin;  // first set column
    std::uint16_t end;    // one past the last
  };
  cv::Size size_;
  std::vector<std::uint32_t> row_starts_;  // rows + 1 offsets into runs_
  std::vector<Run> runs_;
};

}  // namespace segslam::feature
