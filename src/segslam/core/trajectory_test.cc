#include "segslam/core/trajectory.h"

#include <gtest/gtest.h>

namespace segslam::core {
namespace {

geometry::Pose translation(double x) {
  geometry::Pose pose = geometry::Pose::Identity();
  pose.translation().x() = x;
  return pose;
}

TEST(Trajectory, KeepsPosesInTimestampOrder) {
  Trajectory trajectory;
  trajectory.append(1.0, translation(1.0));
  trajectory.append(2.0, translation(2.0));
  EXPECT_EQ(trajectory.size(), 2u);
  EXPECT_EQ(trajectory.timestamps(), (std::vector<double>{1.0, 2.0}));
  EXPECT_THROW(trajectory.append(2.0, translation(3.0)), std::invalid_argument);
  EXPECT_THROW(trajectory.append(1.5, translation(3.0)), std::invalid_argument);
  EXPECT_THROW(Trajectory({{2.0, translation(0)}, {1.0, translation(0)}}), std::invalid_argument);
}

TEST(Trajectory, FindsPoseAtTimestampWithinTolerance) {
  Trajectory trajectory(
      {{1.0, translation(1.0)}, {2.0, translation(2.0)}, {3.0, translation(3.0)}});
  ASSERT_TRUE(trajectory.poseAt(2.0).has_value());
  EXPECT_DOUBLE_EQ(trajectory.poseAt(2.0)->translation().x(), 2.0);
  EXPECT_TRUE(trajectory.poseAt(2.0000005).has_value());
  EXPECT_FALSE(trajectory.poseAt(2.5).has_value());
  EXPECT_FALSE(trajectory.poseAt(0.0).has_value());
  EXPECT_FALSE(trajectory.poseAt(4.0).has_value());
}

}  // namespace
}  // namespace segslam::core
