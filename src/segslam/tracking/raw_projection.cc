#include "segslam/tracking/raw_projection.h"

#include <algorithm>
#include <limits>
#include <opencv2/calib3d.hpp>

#include "segslam/core/undistortion.h"

namespace segslam::tracking {

std::vector<RawProjection> projectIntoRawImage(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const geometry::Pose& T_cw,
    const core::Camera& camera) {
  std::vector<RawProjection> projections;
  std::vector<cv::Point3f> in_camera;
  for (const auto& point : points) {
    if (!point || point->bad) continue;
    const Eigen::Vector3d p_c = T_cw * point->position;
    if (p_c.z() <= 0.0) continue;
    projections.push_back({point, {}, p_c.z()});
    in_camera.emplace_back(static_cast<float>(p_c.x()), static_cast<float>(p_c.y()),
                           static_cast<float>(p_c.z()));
  }
  if (projections.empty()) return projections;
  std::vector<cv::Point2f> pixels;
  cv::projectPoints(in_camera, cv::Vec3d::zeros(), cv::Vec3d::zeros(), core::cameraMatrix(camera),
                    cv::Mat(1, 5, CV_64F, const_cast<double*>(camera.distortion.data())), pixels);
  for (std::size_t k = 0; k < projections.size(); ++k) projections[k].pixel = pixels[k];
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
