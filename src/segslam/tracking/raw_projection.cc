#include "segslam/tracking/raw_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace segslam::tracking {

std::vector<RawProjection> projectIntoRawImage(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const geometry::Pose& T_cw,
    const map::FrameCamera& camera) {
  const auto& K = camera.stereo;
  const int width = camera.camera.width;
  const int height = camera.camera.height;
  const cv::Mat& raw_of = camera.raw_pixel_of_undistorted;
  std::vector<RawProjection> projections;
  for (const auto& point : points) {
    if (!point || point->bad) continue;
    const Eigen::Vector3d p_c = T_cw * point->position;
    if (p_c.z() <= 0.0) continue;
    const int u = static_cast<int>(std::lround(K.fx * p_c.x() / p_c.z() + K.cx));
    const int v = static_cast<int>(std::lround(K.fy * p_c.y() / p_c.z() + K.cy));
    if (u < 0 || v < 0 || u >= width || v >= height) continue;
    const cv::Point2f pixel = raw_of.empty()
                                  ? cv::Point2f(static_cast<float>(u), static_cast<float>(v))
                                  : raw_of.at<cv::Point2f>(v, u);
    projections.push_back({point, pixel, p_c.z()});
  }
  return projections;
}

float nearestDepthAround(const cv::Mat& depth, cv::Point2f pixel, int radius) {
  const int u = cvRound(pixel.x);
  const int v = cvRound(pixel.y);
  if (u - radius < 0 || v - radius < 0 || u + radius >= depth.cols || v + radius >= depth.rows) {
    return 0.0f;
  }
  float nearest = std::numeric_limits<float>::max();
  for (int y = v - radius; y <= v + radius; ++y) {
    const auto* row = depth.ptr<float>(y);
    for (int x = u - radius; x <= u + radius; ++x) {
      if (!(row[x] > 0.0f)) return 0.0f;
      nearest = std::min(nearest, row[x]);
    }
  }
  return nearest;
}

}  // namespace segslam::tracking
