#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace segslam::segmentation {

// Shi-Tomasi corners of an 8-bit grey image, the same corners in the same order as
// cv::goodFeaturesToTrack(gray, corners, max_corners, quality_level, min_distance) gives (3x3
// blocks, 3x3 Sobel, no mask): the local maxima of the smaller eigenvalue of the structure
// tensor that reach quality_level of the strongest, strongest first, none closer than
// min_distance to a stronger one kept. OpenCV computes the gradients, the structure tensor and
// the eigenvalues of the whole image at once: 8 MB of float images for 640x480, on each frame
// the geometric segmenter compares, and the largest transient of a long run with people
// (bench/results/soak.md). Here the eigenvalues are computed a band of rows at a time into one
// float image (1.2 MB), with the band's own gradients and tensor (under 0.5 MB).
std::vector<cv::Point2f> strongestCorners(const cv::Mat& gray, int max_corners,
                                          double quality_level, double min_distance);

}  // namespace segslam::segmentation
