#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/map/frame.h"
#include "segslam/map/map_point.h"

namespace segslam::tracking {

// A map point where a frame's raw (distorted) image sees it: images and depth maps from the
// sensor are registered to the raw image, so comparing a point with them needs the lens
// distortion applied.
struct RawProjection {
  std::shared_ptr<map::MapPoint> point;
  cv::Point2f pixel;
  double depth;  // along the optical axis, metres
};

// Good points in front of the camera that project into the image.
std::vector<RawProjection> projectIntoRawImage(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const geometry::Pose& T_cw,
    const map::FrameCamera& camera);

// Nearest valid depth in the window of this radius around the pixel, or 0 when the window
// leaves the image or has a hole.
float nearestDepthAround(const cv::Mat& depth, cv::Point2f pixel, int radius);

}  // namespace segslam::tracking
