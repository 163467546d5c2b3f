#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace segslam::feature {

// A structuring element that is symmetric about its centre and one run of pixels in each row (a
// disc, an ellipse), as the half width of each row: row dy in [-r, r] spans [-w, w] with
// w = half_widths[dy + r].
using RowHalfWidths = std::vector<int>;

// The disc of pixels within Euclidean distance `radius` (dx^2 + dy^2 <= radius^2, in integers).
RowHalfWidths discHalfWidths(int radius);

// OpenCV's elliptic structuring element of size 2 radius + 1 (getStructuringElement's
// MORPH_ELLIPSE), whose rows are rounded rather than cut at the radius.
RowHalfWidths ellipseHalfWidths(int radius);

// A binary dilation by the element (CV_8UC1 in, non-zero = set; CV_8UC1 out, 255 = set), the same
// pixels as cv::dilate with that element and nothing beyond the image. Per pixel one comparison a
// row of the element, on each row's distance to its nearest set pixel, instead of cv::dilate's one
// maximum per pixel of the element: a 21 x 21 disc costs a tenth.
cv::Mat dilateByRows(const cv::Mat& mask, const RowHalfWidths& half_widths);
// The same into `dilated`, a CV_8UC1 image (or window of one) of the mask's size.
void dilateByRows(const cv::Mat& mask, const RowHalfWidths& half_widths, cv::Mat& dilated);

}  // namespace segslam::feature
