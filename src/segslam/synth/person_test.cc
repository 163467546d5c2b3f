#include "segslam/synth/person.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace segslam::synth {
namespace {

const WalkLane kLane{{1.0, 1.0}, {4.0, 1.0}};

// Lowest and highest point of the body (ellipsoid extents along world z).
std::pair<double, double> verticalExtent(const std::vector<BodyPart>& parts) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const BodyPart& part : parts) {
    const Ellipsoid& e = part.shape;
    // Half-extent of an ellipsoid along z: sqrt(sum_i (r_i * axis_i.z)^2).
    double half = 0.0;
    for (int i = 0; i < 3; ++i) half += std::pow(e.radii[i] * e.axes(2, i), 2);
    half = std::sqrt(half);
    low = std::min(low, e.center.z() - half);
    high = std::max(high, e.center.z() + half);
  }
  return {low, high};
}

TEST(SynthPerson, WalksTheLaneAtItsSpeedAndTurnsAtTheEnds) {
  const Person person(kLane, 1.2, 1.0, 0.0);
  double max_speed = 0.0;
  for (double t = 0.0; t < 20.0; t += 0.05) {
    const PersonPose a = person.poseAt(t);
    const PersonPose b = person.poseAt(t + 0.01);
    ASSERT_NEAR(a.position.y(), 1.0, 1e-12);
    ASSERT_GE(a.position.x(), 1.0 - 1e-12);
    ASSERT_LE(a.position.x(), 4.0 + 1e-12);
    max_speed = std::max(max_speed, (b.position - a.position).norm() / 0.01);
    EXPECT_FALSE(a == b) << "a walking person always moves (t = " << t << ")";
  }
  EXPECT_NEAR(max_speed, 1.2, 1e-6);
  // Out along +x first, then back along -x after the turn.
  EXPECT_NEAR(std::cos(person.poseAt(1.0).heading), 1.0, 1e-9);
  EXPECT_NEAR(std::cos(person.poseAt(2.5 + Person::kTurnSeconds + 1.0).heading), -1.0, 1e-9);
}

TEST(SynthPerson, StandsOnTheFloorAndIsAsTallAsScaled) {
  for (double scale : {0.8, 1.0, 1.3}) {
    const Person person(kLane, 1.0, scale, 0.3);
    EXPECT_DOUBLE_EQ(person.height(), Person::kStandardHeight * scale);
    for (double t = 0.0; t < 3.0; t += 0.1) {
      const auto [low, high] = verticalExtent(person.body(person.poseAt(t)));
      EXPECT_NEAR(low, 0.0, 0.03 * scale) << "t = " << t;
      // The head dips a little while the legs are spread.
      EXPECT_GT(high, 0.95 * person.height()) << "t = " << t;
      EXPECT_LT(high, 1.0 * person.height()) << "t = " << t;
    }
  }
}

TEST(SynthPerson, LimbsSwingWhileWalking) {
  const Person person(kLane, 1.0, 1.0, 0.0);
  const auto first = person.body(person.poseAt(0.2));
  const auto later = person.body(person.poseAt(0.5));
  ASSERT_EQ(first.size(), later.size());
  ASSERT_GE(first.size(), 15u);
  // Relative to the base, some part must have moved: the gait changes the body.
  const Eigen::Vector2d shift = person.poseAt(0.5).position - person.poseAt(0.2).position;
  double largest = 0.0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    const Eigen::Vector3d moved = later[i].shape.center - first[i].shape.center;
    largest = std::max(largest, (moved.head<2>() - shift).norm());
  }
  EXPECT_GT(largest, 0.05);
}

TEST(SynthPerson, StandingStillNeverChanges) {
  const Person person(kLane, 0.0, 1.0, 0.25);
  EXPECT_TRUE(person.poseAt(0.0) == person.poseAt(7.3));
  EXPECT_NEAR(person.poseAt(0.0).position.x(), 1.75, 1e-12);
}

}  // namespace
}  // namespace segslam::synth
