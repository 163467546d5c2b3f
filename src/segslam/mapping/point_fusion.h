#pragma once

#include <memory>
#include <vector>

#include "segslam/map/keyframe.h"
#include "segslam/map/map_point.h"

namespace segslam::mapping {

// Projects map points into a keyframe and merges each with the keypoint it lands on when the
// descriptors agree and the reprojection (with depth) is consistent: a keypoint without a point
// gains an observation; a keypoint that already has another point keeps the one with more
// observations and the other is replaced. Duplicate points of the same world feature would
// otherwise split the constraints in bundle adjustment. Returns the number of fused points.
int fuseIntoKeyFrame(map::KeyFrame& keyframe,
                     const std::vector<std::shared_ptr<map::MapPoint>>& points,
                     double radius_factor = 3.0);

}  // namespace segslam::mapping
