#include "segslam/tracking/free_space_check.h"

#include "segslam/tracking/raw_projection.h"

namespace segslam::tracking {

std::vector<std::shared_ptr<map::MapPoint>> pointsSeenThrough(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const map::Frame& frame,
    const FreeSpaceOptions& options) {
  std::vector<std::shared_ptr<map::MapPoint>> seen_through;
  if (frame.depth_image.empty()) return seen_through;
  for (const auto& projected : projectIntoRawImage(points, frame.T_cw, *frame.camera)) {
    const float measured =
        nearestDepthAround(frame.depth_image, projected.pixel, options.window_radius_px);
    if (measured <= 0.0f) continue;
    if (measured > projected.depth * (1.0 + options.margin_ratio) + options.margin_m) {
      seen_through.push_back(projected.point);
    }
  }
  return seen_through;
}

}  // namespace segslam::tracking
