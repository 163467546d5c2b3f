#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace segslam::feature {

// The dynamic mask dilated by an elliptic disc of `radius` (CV_8UC1, 255 = dynamic), for consumers
// that look up single pixels, such as map point projection. Empty when nothing is dynamic.
// Dilates only around the dynamic pixels' bounding box: several times cheaper than the whole
// frame when objects cover a small part of it, and the same result.
cv::Mat dilateDynamicMask(const cv::Mat& dynamic_mask, int radius);

// Whether the pixel nearest to `pixel` is dynamic (CV_8UC1 mask, non-zero = dynamic); false for
// an empty mask and outside the image.
bool isDynamicAt(const cv::Mat& dynamic_mask, const cv::Point2f& pixel);

// Where keypoints may be extracted, in level-0 pixels: everywhere except within `radius` pixels
// (Euclidean) of a dynamic pixel. The dilation keeps keypoints, and most of their descriptor
// patches, off the border of a moving object, where segmentation is least reliable.
//
// Nothing is dilated up front (a 21 x 21 disc dilation of a 640 x 480 mask costs milliseconds);
// instead an integral image of the raw mask answers "is there a dynamic pixel in this disc or
// rectangle" in constant time per row, and only candidate keypoints are asked.
class StaticMask {
 public:
  // Everything static.
  StaticMask() = default;
  // dynamic_mask: CV_8UC1, non-zero = dynamic; empty = everything static. radius >= 0.
  StaticMask(const cv::Mat& dynamic_mask, int radius);
  // Makes this the mask of another frame in the buffers of the last one: a fresh 1.2 MB integral
  // image every frame was the tracking thread's most frequent page fault (glibc hands a freed
  // block at a heap's top back to the system: ~100 faults a frame on the walker at camera rate).
  void assign(const cv::Mat& dynamic_mask, int radius);

  [[nodiscard]] bool everythingStatic() const { return everything_static_; }
  [[nodiscard]] int radius() const { return radius_; }
  // Whether the level-0 pixel is farther than radius from every dynamic pixel.
  [[nodiscard]] bool isStatic(cv::Point pixel) const;
  // Whether every pixel of the rectangle is static (no dynamic pixel within radius of it).
  [[nodiscard]] bool isStaticRect(const cv::Rect& rect) const;
  // Whether every pixel of the rectangle is dynamic before dilation: nothing there can be static.
  [[nodiscard]] bool isDynamicRect(const cv::Rect& rect) const;

 private:
  // Dynamic pixels in the rectangle, clipped to the image.
  [[nodiscard]] int dynamicPixels(cv::Rect rect) const;

  int radius_ = 0;
  bool everything_static_ = true;
  cv::Mat binary_;    // the mask as 0 / 1
  cv::Mat integral_;  // (rows + 1) x (cols + 1) CV_32S counts of dynamic pixels
  // half_widths_[dy + radius]: the disc of `radius` spans |dx| <= half_widths_ on row dy.
  std::vector<int> half_widths_;
};

}  // namespace segslam::feature
