#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "segslam/dense/keyframe_cloud.h"

namespace segslam::dense {

// The keyframe among `candidates` (camera-to-world poses, at least one) whose view is closest to
// `culled`'s: camera centres nearest, plus 0.5 m per unit of (1 - cosine of the angle between
// the optical axes), so that a keyframe looking the other way from the same spot is far.
std::size_t nearestView(const Eigen::Isometry3d& culled,
                        const std::vector<Eigen::Isometry3d>& candidates);

// `from`'s points (camera frame of T_w_from) moved into the camera frame of T_w_into, added to
// `into` and voxelised again with `voxel_size`: a culled keyframe's view kept in a live one's
// cloud, whose size stays bounded by the space the two saw.
KeyFrameCloud foldInto(const KeyFrameCloud& into, const Eigen::Isometry3d& T_w_into,
                       const KeyFrameCloud& from, const Eigen::Isometry3d& T_w_from,
                       double voxel_size);

}  // namespace segslam::dense
