#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/dense/keyframe_cloud.h"

namespace segslam::dense {

// The keyframe among `candidates` (camera-to-world poses, at least one) whose view is closest to
// `culled`'s: camera centres nearest, plus 0.5 m per unit of (1 - cosine of the angle between
// the optical axes), so that a keyframe looking the other way from the same spot is far.
std::size_t nearestView(const Eigen::Isometry3d& culled,
                        const std::vector<Eigen::Isometry3d>& candidates);

// Keeps what a culled keyframe (`from`, camera frame of T_w_from) saw beyond what `into` (camera
// frame of T_w_into) holds: `from`'s static points, its own and those folded into it before,
// moved into `into`'s frame, where no point of `into` lies in their cell of two voxels or a
// neighbouring one (about 2-4 cm: the same surface seen again), are voxelised and added to
// `into.folded_points`. Re-observed surfaces add nothing,
// so `into` grows with the space the views saw, not with their number. `from`'s dynamic points
// are dropped: they belong to the moment it was made; so are its static points that `into`'s
// depth (`camera`) sees through (FreeSpaceView): what stood there has gone, a person the masks
// missed in `from` or an object moved since.
void foldInto(KeyFrameCloud& into, const Eigen::Isometry3d& T_w_into, const KeyFrameCloud& from,
              const Eigen::Isometry3d& T_w_from, double voxel_size, const core::Camera& camera);

}  // namespace segslam::dense
