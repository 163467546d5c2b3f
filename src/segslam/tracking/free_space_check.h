#pragma once

#include <memory>
#include <vector>

#include "segslam/map/frame.h"
#include "segslam/map/map_point.h"

namespace segslam::tracking {

struct FreeSpaceOptions {
  // The measured surface must lie this much farther than the point (metres, plus a share of the
  // point's depth for the sensor's noise, which grows with depth) ...
  double margin_m = 0.2;
  double margin_ratio = 0.05;
  // ... across the whole window of this radius (pixels) around the point's projection, so that a
  // point on a depth edge, whose projection may fall just beside its own surface, is not blamed.
  int window_radius_px = 2;
};

// Map points that the frame's depth image sees through: at their projection every pixel of the
// window measures a surface clearly behind them. Whatever the point was on has gone: a person
// who walked on, a chair that was pushed. Points without a full valid window, outside the image
// or behind the camera are not judged. The frame needs its pose and depth image.
std::vector<std::shared_ptr<map::MapPoint>> pointsSeenThrough(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const map::Frame& frame,
    const FreeSpaceOptions& options = {});

}  // namespace segslam::tracking
