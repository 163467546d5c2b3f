#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "segslam/synth/primitives.h"

namespace segslam::synth {

// A straight path on the floor (world x, y) that a person walks back and forth along.
struct WalkLane {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::UnitX();
};

// Where a walking person is at one instant. Two equal poses give the identical body.
struct PersonPose {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // base centre on the floor (reference point)
  double heading = 0.0;     // radians from world +x towards +y: the direction the person faces
  double gait_phase = 0.0;  // radians; one walking cycle (two steps) is 2 pi

  bool operator==(const PersonPose& other) const {
    return position == other.position && heading == other.heading && gait_phase == other.gait_phase;
  }
};

enum class BodyMaterial { kShirt = 0, kTrousers, kSkin, kShoes };
inline constexpr int kBodyMaterialCount = 4;

struct BodyPart {
  Ellipsoid shape;  // world frame
  BodyMaterial material;
};

// An articulated person made of ellipsoids (torso, shoulders, pelvis, neck, head, upper and lower
// arms and legs, feet) who walks back and forth along a lane, turns on the spot at its ends and
// swings arms and legs in step.
class Person {
 public:
  static constexpr double kStandardHeight = 1.75;  // metres at scale 1
  static constexpr double kTurnSeconds = 0.8;      // time for a half turn at a lane end

  // `speed` in m/s (0: stands still, facing along the lane); `scale` multiplies the standard
  // height; `start_fraction` in [0, 1) says where in its back-and-forth cycle the person is at
  // time 0.
  Person(WalkLane lane, double speed, double scale, double start_fraction);

  [[nodiscard]] PersonPose poseAt(double t) const;
  [[nodiscard]] std::vector<BodyPart> body(const PersonPose& pose) const;
  [[nodiscard]] double height() const { return height_; }
  // Size (metres) of a texture that covers any body part once.
  [[nodiscard]] Eigen::Vector2d textureExtent() const;

 private:
  [[nodiscard]] PersonPose poseOnCycle(double cycle_time) const;
  [[nodiscard]] double cycleSeconds() const;
  void addLeg(double side, double gait_phase, std::vector<BodyPart>& parts) const;
  void addArm(double side, double gait_phase, std::vector<BodyPart>& parts) const;

  WalkLane lane_;
  double speed_;
  double height_;
  double start_fraction_;
};

}  // namespace segslam::synth
