#include "segslam/tracking/late_mask_check.h"

#include <cmath>

#include "segslam/tracking/raw_projection.h"

namespace segslam::tracking {

std::vector<std::shared_ptr<map::MapPoint>> pointsOnDynamicSurface(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const geometry::Pose& T_cw,
    const map::FrameCamera& camera, const cv::Mat& dynamic_mask, const cv::Mat& depth,
    const DynamicSurfaceOptions& options) {
  std::vector<std::shared_ptr<map::MapPoint>> on_dynamic_surface;
  if (dynamic_mask.empty() || depth.empty()) return on_dynamic_surface;
  int on_any_surface = 0;
  for (const auto& projected : projectIntoRawImage(points, T_cw, camera)) {
    const int u = cvRound(projected.pixel.x);
    const int v = cvRound(projected.pixel.y);
    if (u < 0 || v < 0 || u >= dynamic_mask.cols || v >= dynamic_mask.rows) continue;
    const float measured = depth.at<float>(v, u);
    if (!(measured > 0.0f)) continue;
    const double tolerance = options.tolerance_m + options.tolerance_ratio * projected.depth;
    if (std::abs(measured - projected.depth) >= tolerance) continue;
    ++on_any_surface;
    if (dynamic_mask.at<std::uint8_t>(v, u) != 0) on_dynamic_surface.push_back(projected.point);
  }
  const bool implausible =
      on_any_surface >= options.min_points_to_judge &&
      static_cast<double>(on_dynamic_surface.size()) > options.max_dynamic_share * on_any_surface;
  if (implausible) on_dynamic_surface.clear();
  return on_dynamic_surface;
}

}  // namespace segslam::tracking
