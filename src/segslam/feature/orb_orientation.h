#pragma once

#include <opencv2/core.hpp>

namespace segslam::feature {

// Radius of the circular patch whose intensity centroid gives a keypoint its orientation. A disc
// (not a square) keeps the moments the same under rotation of the image.
inline constexpr int kOrientationRadius = 15;

// Orientation by intensity centroid (Rublee et al. 2011): the direction, in degrees in [0, 360),
// from `center` to the centroid (m10 / m00, m01 / m00) of the image intensity over the disc of
// kOrientationRadius around it, measured like cv::KeyPoint::angle (x to the right, y down).
// `image` is CV_8UC1 and `center` at least kOrientationRadius from its border.
float intensityCentroidAngle(const cv::Mat& image, cv::Point center);

}  // namespace segslam::feature
