#include "segslam/dense/keyframe_fold.h"

#include <gtest/gtest.h>

namespace segslam::dense {
namespace {

Eigen::Isometry3d at(double x, double y, double z, double yaw = 0.0) {
  Eigen::Isometry3d pose(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()));
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

// 640 x 480 pixels, 525 px focal length: at 1 m it sees x in [-0.61, 0.61], y in [-0.46, 0.46].
core::Camera kinectCamera() {
  core::Camera c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 525.0;
  c.cx = 319.5;
  c.cy = 239.5;
  return c;
}

// A 1 cm grid of a wall 1 m in front of the camera, x from x_min to x_max (camera frame).
LabelledCloud wall(float x_min, float x_max, std::uint8_t grey) {
  LabelledCloud cloud;
  for (float x = x_min; x < x_max; x += 0.01f) {
    for (float y = -0.2f; y < 0.2f; y += 0.01f) cloud.add({x, y, 1.0f}, {grey, grey, grey});
  }
  return cloud;
}

TEST(KeyFrameFold, TheNearestViewIsNearAndLooksTheSameWay) {
  const std::vector<Eigen::Isometry3d> candidates = {at(0.0, 0.0, 0.0, M_PI), at(0.4, 0.0, 0.0),
                                                     at(3.0, 0.0, 0.0)};
  // The first stands on the spot but looks back: the second, 0.4 m away, sees the same.
  EXPECT_EQ(nearestView(at(0.0, 0.0, 0.0), candidates), 1u);
  EXPECT_EQ(nearestView(at(2.8, 0.0, 0.0), candidates), 2u);
}

TEST(KeyFrameFold, OnlyWhatTheLiveKeyFrameDidNotSeeIsFoldedInAndOnlyOnce) {
  KeyFrameCloud live;
  live.static_points = wall(-0.3f, 0.3f, 10);
  KeyFrameCloud culled;  // 0.2 m to the left of the live one: the wall from -0.5 to 0.1 m
  culled.static_points = wall(-0.3f, 0.3f, 50);
  culled.dynamic_points.add({0.0f, 0.0f, 0.5f}, {1, 2, 3}, 15);
  foldInto(live, at(0.0, 0.0, 0.0), culled, at(-0.2, 0.0, 0.0), 0.01, kinectCamera());
  ASSERT_GT(live.folded_points.size(), 0u);
  for (const Eigen::Vector3f& p : live.folded_points.points) {
    EXPECT_LT(p.x(), -0.31f) << "only the strip the live keyframe did not see";
    EXPECT_NEAR(p.z(), 1.0f, 1e-5f);
  }
  EXPECT_EQ(live.static_points.size(), wall(-0.3f, 0.3f, 10).size()) << "its own view unchanged";
  EXPECT_TRUE(live.dynamic_points.empty()) << "a culled keyframe's moving objects are gone";

  const std::size_t folded = live.folded_points.size();
  foldInto(live, at(0.0, 0.0, 0.0), culled, at(-0.2, 0.0, 0.0), 0.01, kinectCamera());
  EXPECT_EQ(live.folded_points.size(), folded) << "the same view again adds nothing";
}

TEST(KeyFrameFold, WhatWasFoldedIntoACulledKeyFrameIsFoldedOn) {
  KeyFrameCloud culled;
  culled.folded_points = wall(0.5f, 0.6f, 70);  // seen by a keyframe culled earlier
  KeyFrameCloud live;
  foldInto(live, at(0.0, 0.0, 0.0), culled, at(0.0, 0.0, 0.0), 0.01, kinectCamera());
  EXPECT_EQ(live.folded_points.size(), voxelDownsample(culled.folded_points, 0.01).size());
  EXPECT_EQ(live.folded_points.colours.front()[0], 70);
}

TEST(KeyFrameFold, WhatTheLiveKeyFrameSeesThroughIsNotFoldedIn) {
  KeyFrameCloud live;  // the wall, nothing in front of it
  live.static_points = wall(-0.3f, 0.3f, 10);
  KeyFrameCloud culled;  // from the same spot, a person the masks missed half a metre in front
  culled.static_points = wall(-0.3f, 0.3f, 50);
  for (float x = -0.1f; x < 0.1f; x += 0.01f) {
    for (float y = -0.08f; y < 0.08f; y += 0.01f) culled.static_points.add({x, y, 0.5f}, {9, 9, 9});
  }
  foldInto(live, at(0.0, 0.0, 0.0), culled, at(0.0, 0.0, 0.0), 0.01, kinectCamera());
  EXPECT_EQ(live.folded_points.size(), 0u);
}

TEST(KeyFrameFold, WhatTheLiveKeyFrameDidNotLookAtIsFoldedInWhateverItsDepth) {
  KeyFrameCloud live;  // the right half of the wall only
  live.static_points = wall(0.0f, 0.3f, 10);
  KeyFrameCloud culled;  // a box on the left, in front of where the wall would be
  for (float x = -0.3f; x < -0.1f; x += 0.01f) {
    for (float y = -0.2f; y < 0.2f; y += 0.01f) culled.static_points.add({x, y, 0.5f}, {9, 9, 9});
  }
  foldInto(live, at(0.0, 0.0, 0.0), culled, at(0.0, 0.0, 0.0), 0.01, kinectCamera());
  EXPECT_EQ(live.folded_points.size(), voxelDownsample(culled.static_points, 0.01).size());
}

}  // namespace
}  // namespace segslam::dense
