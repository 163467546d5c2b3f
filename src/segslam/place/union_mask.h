#pragma once

#include <opencv2/core.hpp>

// The union mask of a pair of images: the pixels static in both (the method's "union" of the two
// dynamic masks), and its forms on a feature map's grid. Static masks are CV_8UC1 with 255 =
// static, 0 = dynamic; an empty mask means everything is static.
namespace segslam::place {

// Static in both; empty when both are empty. Masks must have the same size when both are given.
cv::Mat unionStaticMask(const cv::Mat& a, const cv::Mat& b);

// Share of static pixels in each cell of a `grid` (width x height cells laid over the mask),
// CV_32FC1 in [0, 1]; all ones for an empty mask.
cv::Mat staticFraction(const cv::Mat& static_mask, cv::Size grid);

// The static area shrunk by `radius_px` pixels, so that what remains is at least that far from
// anything dynamic: a feature whose receptive field reaches a moving object is not static.
cv::Mat erodeStaticMask(const cv::Mat& static_mask, int radius_px);

}  // namespace segslam::place
