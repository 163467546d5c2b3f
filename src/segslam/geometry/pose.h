#pragma once

#include <Eigen/Geometry>

namespace segslam::geometry {

// Rigid transform. By convention a camera pose is T_wc: it maps camera coordinates to world
// coordinates (the TUM "camera-to-world" convention).
using Pose = Eigen::Isometry3d;

// Pose from a translation and a (not necessarily normalised) quaternion.
Pose poseFromTranslationQuaternion(const Eigen::Vector3d& t, const Eigen::Quaterniond& q);

// The same transform with its rotation block projected back onto SO(3). Composing poses
// (velocity = T_k * T_{k-1}^-1, prediction = velocity * T_k) feeds rounding errors back into
// Isometry3d::inverse(), which assumes an orthonormal block; unchecked, the block's scale grows
// by about 2.4x per frame and the pose drifts along the optical axis within a few dozen frames.
Pose orthonormalised(const Pose& pose);

// Rotation angle of a transform in radians, acos((trace(R) - 1) / 2) clamped to [0, pi].
double rotationAngle(const Pose& pose);

// Rotation angle via the quaternion, accurate for tiny angles too.
double rotationAngleAccurate(const Pose& pose);

}  // namespace segslam::geometry
