#include "segslam/synth/camera_path.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "segslam/geometry/angles.h"

namespace segslam::synth {

namespace {

using geometry::kDegree;
using geometry::kPi;

const Eigen::Vector3d kXyzBase(0.95, 2.5, 1.45);
constexpr double kXyzPitch = -17.0 * kDegree;

// Camera looking along (yaw from world +x towards +y, pitch up from the horizontal), then rolled
// about its optical axis; its x axis stays horizontal before the roll.
Eigen::Matrix3d cameraRotation(double yaw, double pitch, double roll) {
  const Eigen::Vector3d forward(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                                std::sin(pitch));
  const Eigen::Vector3d right(std::sin(yaw), -std::cos(yaw), 0.0);
  Eigen::Matrix3d rotation;
  rotation.col(0) = right;
  rotation.col(1) = forward.cross(right);
  rotation.col(2) = forward;
  return rotation * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

geometry::Pose makePose(const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation) {
  geometry::Pose pose = geometry::Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = position;
  return pose;
}

double wave(double t, double period, double phase) {
  return std::sin(2.0 * kPi * t / period + phase);
}

geometry::Pose xyzPose(double t) {
  constexpr double kPeriod = 4.0;
  constexpr double kAmplitude = 0.2;
  const double cycles = t / kPeriod;
  const double whole = std::floor(cycles);
  const int axis = static_cast<int>(whole) % 3;
  const double tau = cycles - whole;
  // Out and back through the start, with zero velocity where one axis hands over to the next.
  const double offset = kAmplitude * std::sin(2.0 * kPi * tau) * std::sin(kPi * tau);
  const Eigen::Vector3d position =
      kXyzBase + cameraRotation(0.0, kXyzPitch, 0.0).col(axis) * offset;
  const double yaw = 6.0 * kDegree * wave(t, 5.1, 0.0);
  const double pitch = kXyzPitch + 4.0 * kDegree * wave(t, 6.3, 1.0);
  const double roll = 3.0 * kDegree * wave(t, 7.7, 2.0);
  return makePose(position, cameraRotation(yaw, pitch, roll));
}

// tau in [0, 1): fraction of the lap.
geometry::Pose loopPose(double tau) {
  const Eigen::Vector3d centre(1.2, 2.5, 1.4);
  constexpr double kRadius = 0.45;
  const double angle = kPi + 2.0 * kPi * tau;
  const Eigen::Vector3d position =
      centre + Eigen::Vector3d(kRadius * std::cos(angle), kRadius * std::sin(angle),
                               0.08 * std::sin(4.0 * kPi * tau));
  const double turn = std::sin(kPi * tau);
  const double yaw = 70.0 * kDegree * turn * turn;
  const double pitch = -12.0 * kDegree + 3.0 * kDegree * std::sin(2.0 * kPi * tau);
  const double roll = 2.0 * kDegree * std::sin(4.0 * kPi * tau);
  return makePose(position, cameraRotation(yaw, pitch, roll));
}

// tau in [0, 1): fraction of the lap. The camera walks a circle around the room's centre while
// turning once all the way round, so the start's view comes back only at the end: a loop whose
// two ends share no keyframes.
geometry::Pose roomLoopPose(double tau) {
  const Eigen::Vector3d centre(2.6, 2.5, 1.4);
  constexpr double kRadius = 0.6;
  const double angle = kPi + 2.0 * kPi * tau;
  const Eigen::Vector3d position =
      centre + Eigen::Vector3d(kRadius * std::cos(angle), kRadius * std::sin(angle),
                               0.06 * std::sin(4.0 * kPi * tau));
  const double yaw = angle + kPi;  // facing away from the centre, towards the walls
  const double pitch = -10.0 * kDegree + 4.0 * kDegree * std::sin(2.0 * kPi * tau);
  const double roll = 2.0 * kDegree * std::sin(4.0 * kPi * tau);
  return makePose(position, cameraRotation(yaw, pitch, roll));
}

}  // namespace

std::vector<geometry::Pose> cameraTrajectory(const SynthOptions& options) {
  std::vector<geometry::Pose> poses;
  poses.reserve(options.frames);
  const int span = std::max(options.frames - 1, 1);
  for (int k = 0; k < options.frames; ++k) {
    // Position on the circuit in laps, wrapped to [0, 1): the last frame is the first pose
    // again, exactly.
    const long long progress = static_cast<long long>(k) * options.laps;
    const double tau = static_cast<double>(progress % span) / span;
    if (options.path == "loop") {
      poses.push_back(loopPose(tau));
    } else if (options.path == "room") {
      poses.push_back(roomLoopPose(tau));
    } else if (options.path == "xyz") {
      poses.push_back(xyzPose(k / kSynthFps));
    } else {
      poses.push_back(xyzPose(0.0));
    }
  }
  return poses;
}

}  // namespace segslam::synth
