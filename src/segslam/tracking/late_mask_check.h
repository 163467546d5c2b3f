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
  // A mask that claims more than this share of the points lying on the surface its frame measured
  // is a segmentation failure (the camera's own motion taken for an object's), not a mover:
  // culling them would wipe out the local map, and tracking with it. Judged once the frame sees at
  // least min_points_to_judge such points.
  double max_dynamic_share = 0.5;
  int min_points_to_judge = 20;
};

// Map points on a moving object that an earlier frame's dynamic mask, arrived late, shows: they
// project into the mask and lie on the surface that frame measured there. A network's mask
// arrives hundreds of milliseconds after its frame; points made meanwhile on the person (whom
// the mask carried from an older output missed) are found this way.
// T_cw, dynamic_mask (CV_8U, non-zero = dynamic) and depth (CV_32F metres) are that frame's.
// Nothing is found when the mask claims most of the surface (see max_dynamic_share).
std::vector<std::shared_ptr<map::MapPoint>> pointsOnDynamicSurface(
    const std::vector<std::shared_ptr<map::MapPoint>>& points, const geometry::Pose& T_cw,
    const map::FrameCamera& camera, const cv::Mat& dynamic_mask, const cv::Mat& depth,
    const DynamicSurfaceOptions& options = {});

}  // namespace segslam::tracking
