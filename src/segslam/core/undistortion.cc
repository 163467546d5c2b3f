#include "segslam/core/undistortion.h"

#include <opencv2/calib3d.hpp>

namespace segslam::core {

cv::Mat cameraMatrix(const Camera& camera) {
  return (cv::Mat_<double>(3, 3) << camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
}

std::vector<cv::Point2f> undistortPixels(const std::vector<cv::Point2f>& pixels,
                                         const Camera& camera) {
  if (!camera.hasDistortion() || pixels.empty()) return pixels;
  const cv::Mat k = cameraMatrix(camera);
  const cv::Mat distortion = cv::Mat(1, 5, CV_64F, const_cast<double*>(camera.distortion.data()));
  std::vector<cv::Point2f> undistorted;
  cv::undistortPoints(pixels, undistorted, k, distortion.clone(), cv::noArray(), k);
  return undistorted;
}

}  // namespace segslam::core
