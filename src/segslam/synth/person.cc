#include "segslam/synth/person.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "segslam/geometry/angles.h"

namespace segslam::synth {

namespace {

using geometry::kDegree;
using geometry::kPi;

// Body proportions as fractions of the height.
constexpr double kStepLength = 0.4;
constexpr double kHipHeight = 0.53;
constexpr double kHipSide = 0.055;
constexpr double kThighLength = 0.245;
constexpr double kShinLength = 0.245;
constexpr double kShoulderHeight = 0.815;
constexpr double kShoulderSide = 0.135;
constexpr double kUpperArmLength = 0.175;
constexpr double kForearmLength = 0.16;

constexpr double kHipSwing = 20.0 * kDegree;
constexpr double kKneeFlex = 40.0 * kDegree;
constexpr double kArmSwing = 22.0 * kDegree;
constexpr double kElbowFlex = 20.0 * kDegree;

double smoothStep(double x) { return x * x * (3.0 - 2.0 * x); }

double headingOf(const Eigen::Vector2d& direction) {
  return std::atan2(direction.y(), direction.x());
}

Ellipsoid axisAligned(const Eigen::Vector3d& center, const Eigen::Vector3d& radii) {
  Ellipsoid e;
  e.center = center;
  e.radii = radii;
  return e;
}

// Direction in the person's x-z plane (tilted outwards by `outwards` along y), `angle` forwards
// from straight down.
Eigen::Vector3d limbDirection(double angle, double outwards) {
  return Eigen::Vector3d(std::sin(angle), outwards, -std::cos(angle)).normalized();
}

}  // namespace

Person::Person(WalkLane lane, double speed, double scale, double start_fraction)
    : lane_(std::move(lane)),
      speed_(speed),
      height_(kStandardHeight * scale),
      start_fraction_(start_fraction) {}

double Person::cycleSeconds() const {
  return 2.0 * ((lane_.b - lane_.a).norm() / speed_ + kTurnSeconds);
}

PersonPose Person::poseAt(double t) const {
  if (speed_ <= 0.0) {
    return {lane_.a + start_fraction_ * (lane_.b - lane_.a), headingOf(lane_.b - lane_.a), 0.0};
  }
  const double cycle = cycleSeconds();
  const double time = t + start_fraction_ * cycle;
  PersonPose pose = poseOnCycle(std::fmod(time, cycle));
  pose.gait_phase = kPi * speed_ * time / (kStepLength * height_);
  return pose;
}

PersonPose Person::poseOnCycle(double cycle_time) const {
  const Eigen::Vector2d forward = lane_.b - lane_.a;
  const double walk = forward.norm() / speed_;
  const double out_heading = headingOf(forward);
  PersonPose pose;
  if (cycle_time < walk) {
    pose.position = lane_.a + forward * (cycle_time / walk);
    pose.heading = out_heading;
  } else if (cycle_time < walk + kTurnSeconds) {
    pose.position = lane_.b;
    pose.heading = out_heading + kPi * smoothStep((cycle_time - walk) / kTurnSeconds);
  } else if (cycle_time < 2.0 * walk + kTurnSeconds) {
    pose.position = lane_.b - forward * ((cycle_time - walk - kTurnSeconds) / walk);
    pose.heading = out_heading + kPi;
  } else {
    pose.position = lane_.a;
    const double turned = (cycle_time - 2.0 * walk - kTurnSeconds) / kTurnSeconds;
    pose.heading = out_heading + kPi + kPi * smoothStep(std::min(turned, 1.0));
  }
  return pose;
}

Eigen::Vector2d Person::textureExtent() const { return {0.7 * height_, 0.6 * height_}; }

void Person::addLeg(double side, double gait_phase, std::vector<BodyPart>& parts) const {
  const double h = height_;
  const double swing = side * kHipSwing * std::sin(gait_phase);
  // The knee bends while the leg swings forwards, most when it passes under the hip.
  const double flex = kKneeFlex * std::max(0.0, side * std::cos(gait_phase));
  const Eigen::Vector3d hip(0.0, side * kHipSide * h, kHipHeight * h);
  const Eigen::Vector3d knee = hip + kThighLength * h * limbDirection(swing, 0.0);
  const Eigen::Vector3d ankle = knee + kShinLength * h * limbDirection(swing - flex, 0.0);
  const Eigen::Vector3d heel = ankle + Eigen::Vector3d(-0.02 * h, 0.0, -0.018 * h);
  const Eigen::Vector3d toe = ankle + Eigen::Vector3d(0.1 * h, 0.0, -0.018 * h);
  parts.push_back({limbBetween(hip, knee, 0.045 * h, 0.02 * h), BodyMaterial::kTrousers});
  parts.push_back({limbBetween(knee, ankle, 0.034 * h, 0.015 * h), BodyMaterial::kTrousers});
  parts.push_back({limbBetween(heel, toe, 0.024 * h, 0.01 * h), BodyMaterial::kShoes});
}

void Person::addArm(double side, double gait_phase, std::vector<BodyPart>& parts) const {
  const double h = height_;
  // Arms swing against the leg of the same side.
  const double swing = -side * kArmSwing * std::sin(gait_phase);
  const Eigen::Vector3d shoulder(0.0, side * kShoulderSide * h, kShoulderHeight * h);
  const Eigen::Vector3d elbow = shoulder + kUpperArmLength * h * limbDirection(swing, side * 0.1);
  const Eigen::Vector3d hand =
      elbow + kForearmLength * h * limbDirection(swing + kElbowFlex, side * 0.05);
  parts.push_back({limbBetween(shoulder, elbow, 0.028 * h, 0.015 * h), BodyMaterial::kShirt});
  parts.push_back({limbBetween(elbow, hand, 0.024 * h, 0.012 * h), BodyMaterial::kSkin});
}

std::vector<BodyPart> Person::body(const PersonPose& pose) const {
  const double h = height_;
  std::vector<BodyPart> parts;
  parts.push_back(
      {axisAligned({0.0, 0.0, 0.695 * h}, {0.07 * h, 0.115 * h, 0.145 * h}), BodyMaterial::kShirt});
  parts.push_back(
      {axisAligned({0.0, 0.0, 0.79 * h}, {0.06 * h, 0.145 * h, 0.045 * h}), BodyMaterial::kShirt});
  parts.push_back({axisAligned({0.0, 0.0, 0.54 * h}, {0.065 * h, 0.1 * h, 0.065 * h}),
                   BodyMaterial::kTrousers});
  parts.push_back({limbBetween({0.0, 0.0, 0.82 * h}, {0.0, 0.0, 0.875 * h}, 0.03 * h, 0.01 * h),
                   BodyMaterial::kSkin});
  parts.push_back({axisAligned({0.005 * h, 0.0, 0.925 * h}, {0.056 * h, 0.05 * h, 0.066 * h}),
                   BodyMaterial::kSkin});
  for (double side : {1.0, -1.0}) {
    addLeg(side, pose.gait_phase, parts);
    addArm(side, pose.gait_phase, parts);
  }
  // Lower the body so that the straighter leg stands on the floor.
  const double drop =
      (kThighLength + kShinLength) * h * (1.0 - std::cos(kHipSwing * std::sin(pose.gait_phase)));
  geometry::Pose to_world = geometry::Pose::Identity();
  to_world.translation() = Eigen::Vector3d(pose.position.x(), pose.position.y(), -drop);
  to_world.linear() = Eigen::AngleAxisd(pose.heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (auto& part : parts) part.shape = transformed(to_world, part.shape);
  return parts;
}

}  // namespace segslam::synth
