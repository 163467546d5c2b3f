#include "segslam/tracking/late_mask_check.h"

#include <cmath>

#include "segslam/tracking/raw_projection.h"

namespace segslam::tracking {

std::vector<std::shared_ptr<map::MapPoint>> pointsOnDynamicSurface(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const geometry::Pose& T_cw,
    const map::FrameCamera& camera, const cv::Mat& dynamic_mask, const cv::Mat& depth,
    const DynamicSurfaceOptions& options) {
  std::vector<std::shared_ptr<map::MapPoint>> on_surface;
  if (dynamic_mask.empty() || depth.empty()) return on_surface;
  for (const auto& projected : projectIntoRawImage(points, T_cw, camera)) {
    const int u = cvRound(projected.pixel.x);
    const int v = cvRound(projected.pixel.y);
    if (u < 0 || v < 0 || u >= dynamic_mask.cols || v >= dynamic_mask.rows) continue;
    if (dynamic_mask.at<std::uint8_t>(v, u) == 0) continue;
    const float measured = depth.at<float>(v, u);
    if (!(measured > 0.0f)) continue;
    const double tolerance = options.tolerance_m + options.tolerance_ratio * projected.depth;
    if (std::abs(measured - projected.depth) < tolerance) on_surface.push_back(projected.point);
  }
  return on_surface;
}

}  // namespace segslam::tracking
