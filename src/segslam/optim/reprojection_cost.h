#pragma once

#include <ceres/cost_function.h>

#include <memory>

#include "segslam/optim/rgbd_observation.h"

namespace segslam::optim {

// The bundle adjuster's residual for one observation, with analytic Jacobians:
// sqrt(information) * (observed - predicted) for (u, v, u_r). Without depth the u_r row is
// constantly zero: every residual block then has the same size, which lets Ceres use its
// fixed-size Schur eliminator (several times faster than the dynamic one). Its parameter
// blocks are the keyframe's rotation as an Eigen quaternion (x, y, z, w; use it with
// ceres::EigenQuaternionManifold), the keyframe's translation (T_cw = [R(q) | t]) and the
// point's world position. Evaluation fails while the point is not in front of the camera, so
// the solver rejects steps that would move it behind.
[[nodiscard]] std::unique_ptr<ceres::CostFunction> makeReprojectionCost(
    const StereoIntrinsics& intrinsics, const RgbdObservation& observation);

}  // namespace segslam::optim
