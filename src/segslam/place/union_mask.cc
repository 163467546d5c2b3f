#include "segslam/place/union_mask.h"

#include <opencv2/imgproc.hpp>

#include "segslam/util/error.h"

namespace segslam::place {

cv::Mat unionStaticMask(const cv::Mat& a, const cv::Mat& b) {
  if (a.empty()) return b.clone();
  if (b.empty()) return a.clone();
  if (a.size() != b.size()) {
    throw util::Error("union mask: static masks of different sizes");
  }
  cv::Mat both;
  cv::bitwise_and(a, b, both);
  return both;
}

cv::Mat staticFraction(const cv::Mat& static_mask, cv::Size grid) {
  if (static_mask.empty()) return cv::Mat(grid, CV_32FC1, cv::Scalar(1.0));
  cv::Mat unit;
  static_mask.convertTo(unit, CV_32F, 1.0 / 255.0);
  cv::Mat fraction;
  cv::resize(unit, fraction, grid, 0, 0, cv::INTER_AREA);
  return fraction;
}

cv::Mat erodeStaticMask(const cv::Mat& static_mask, int radius_px) {
  if (static_mask.empty() || radius_px <= 0) return static_mask.clone();
  const cv::Mat disc =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius_px + 1, 2 * radius_px + 1));
  cv::Mat eroded;
  cv::erode(static_mask, eroded, disc);
  return eroded;
}

}  // namespace segslam::place
