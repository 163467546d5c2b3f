#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/map/frame.h"
#include "segslam/map/map_point.h"

namespace segslam::tracking {

struct DynamicSurfaceOptions {
  // How close (metres, plus a share of the depth) a point must lie to the measured surface to
  // count as on it; a point of the background behind the moving object is farther.
  double tolerance_m = 0.1;
  double tolerance_ratio = 0.05;
};

// Map points on a moving object that an earlier frame's dynamic mask, arrived late, shows: they
// project into the mask and lie on the surface that frame measured there. A network's mask
// arrives hundreds of milliseconds after its frame; points made meanwhile on the person (whom
// the mask carried from an older output missed) are found this way.
// T_cw, dynamic_mask (CV_8U, non-zero = dynamic) and depth (CV_32F metres) are that frame's.
std::vector<std::shared_ptr<map::MapPoint>> pointsOnDynamicSurface(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const geometry::Pose& T_cw,
    const map::FrameCamera& camera, const cv::Mat& dynamic_mask, const cv::Mat& depth,
    const DynamicSurfaceOptions& options = {});

}  // namespace segslam::tracking
