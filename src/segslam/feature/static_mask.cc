#include "segslam/feature/static_mask.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "segslam/feature/mask_dilation.h"

namespace segslam::feature {

bool isDynamicAt(const cv::Mat& dynamic_mask, const cv::Point2f& pixel) {
  if (dynamic_mask.empty()) return false;
  const int x = cvRound(pixel.x);
  const int y = cvRound(pixel.y);
  return x >= 0 && y >= 0 && x < dynamic_mask.cols && y < dynamic_mask.rows &&
         dynamic_mask.at<std::uint8_t>(y, x) != 0;
}

cv::Mat dilateDynamicMask(const cv::Mat& dynamic_mask, int radius) {
  if (dynamic_mask.empty()) return {};
  if (dynamic_mask.type() != CV_8UC1) {
    throw std::invalid_argument("dilateDynamicMask: dynamic mask must be CV_8UC1");
  }
  const cv::Rect box = cv::boundingRect(dynamic_mask);
  if (box.empty()) return {};
  cv::Mat dilated = cv::Mat::zeros(dynamic_mask.size(), CV_8UC1);
  if (radius <= 0) {
    cv::threshold(dynamic_mask(box), dilated(box), 0, 255, cv::THRESH_BINARY);
    return dilated;
  }
  const cv::Rect around =
      cv::Rect(box.x - radius, box.y - radius, box.width + 2 * radius, box.height + 2 * radius) &
      cv::Rect(0, 0, dynamic_mask.cols, dynamic_mask.rows);
  cv::Mat window = dilated(around);
  dilateByRows(dynamic_mask(around), ellipseHalfWidths(radius), window);
  return dilated;
}

StaticMask::StaticMask(const cv::Mat& dynamic_mask, int radius) { assign(dynamic_mask, radius); }

void StaticMask::assign(const cv::Mat& dynamic_mask, int radius) {
  if (radius < 0) {
    throw std::invalid_argument("StaticMask: dilation radius must be >= 0, got " +
                                std::to_string(radius));
  }
  if (!dynamic_mask.empty() && dynamic_mask.type() != CV_8UC1) {
    throw std::invalid_argument("StaticMask: dynamic mask must be CV_8UC1");
  }
  if (radius != radius_ || half_widths_.empty()) {
    half_widths_ = discHalfWidths(radius);
    radius_ = radius;
  }
  everything_static_ = dynamic_mask.empty();
  if (everything_static_) return;
  cv::threshold(dynamic_mask, binary_, 0, 1, cv::THRESH_BINARY);
  cv::integral(binary_, integral_, CV_32S);
}

int StaticMask::dynamicPixels(cv::Rect rect) const {
  rect &= cv::Rect(0, 0, integral_.cols - 1, integral_.rows - 1);
  if (rect.empty()) return 0;
  const int x0 = rect.x;
  const int x1 = rect.x + rect.width;
  const int* top = integral_.ptr<int>(rect.y);
  const int* bottom = integral_.ptr<int>(rect.y + rect.height);
  return bottom[x1] - bottom[x0] - top[x1] + top[x0];
}

bool StaticMask::isStatic(cv::Point pixel) const {
  if (everythingStatic()) return true;
  for (int dy = -radius_; dy <= radius_; ++dy) {
    const int half_width = half_widths_[dy + radius_];
    if (dynamicPixels({pixel.x - half_width, pixel.y + dy, 2 * half_width + 1, 1}) > 0) {
      return false;
    }
  }
  return true;
}

bool StaticMask::isStaticRect(const cv::Rect& rect) const {
  if (everythingStatic()) return true;
  // The rectangle grown by radius holds the dilated rectangle, so this is slightly conservative
  // at the corners; it only decides whether per-pixel checks can be skipped.
  const cv::Rect grown(rect.x - radius_, rect.y - radius_, rect.width + 2 * radius_,
                       rect.height + 2 * radius_);
  return dynamicPixels(grown) == 0;
}

bool StaticMask::isDynamicRect(const cv::Rect& rect) const {
  if (everythingStatic()) return false;
  return dynamicPixels(rect) == rect.area();
}

}  // namespace segslam::feature
