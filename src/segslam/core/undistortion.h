#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segslam/core/camera.h"

// The camera as OpenCV's calibration functions take it, shared by everything that undistorts.
namespace segslam::core {

// 3 x 3 CV_64F intrinsic matrix K.
cv::Mat cameraMatrix(const Camera& camera);

// Pixel positions with the lens distortion removed, in the same pinhole camera (P = K).
std::vector<cv::Point2f> undistortPixels(const std::vector<cv::Point2f>& pixels,
                                         const Camera& camera);

}  // namespace segslam::core
