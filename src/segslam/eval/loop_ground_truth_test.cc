#include "segslam/eval/loop_ground_truth.h"

#include <gtest/gtest.h>

#include <numbers>

namespace segslam::eval {
namespace {

core::StampedPose poseAt(double t, double x, double yaw_deg) {
  geometry::Pose pose = geometry::Pose::Identity();
  pose.translate(Eigen::Vector3d(x, 0.0, 0.0));
  pose.rotate(Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY()));
  return {t, pose};
}

TEST(LoopGroundTruth, LabelsPairsByTranslationRotationAndTimeGap) {
  const std::vector<core::StampedPose> poses = {
      poseAt(0.0, 0.0, 0.0),    // 0
      poseAt(1.0, 0.05, 0.0),   // 1: too soon after 0
      poseAt(10.0, 0.1, 5.0),   // 2: loop with 0 and 1
      poseAt(20.0, 1.0, 0.0),   // 3: too far from everything
      poseAt(30.0, 0.0, 45.0),  // 4: same place as 0, turned too far
  };
  LoopThresholds thresholds;  // 0.3 m, 20 deg, 5 s
  const auto pairs = loopPairs(poses, thresholds);
  // (0,1) is too close in time; every other of the 10 pairs is scored.
  ASSERT_EQ(pairs.size(), 9u);
  auto find = [&](std::size_t i, std::size_t j) {
    for (const auto& pair : pairs) {
      if (pair.i == i && pair.j == j) return pair;
    }
    ADD_FAILURE() << "pair " << i << "," << j << " missing";
    return LoopPair{};
  };
  EXPECT_TRUE(find(0, 2).loop);
  EXPECT_NEAR(find(0, 2).translation_m, 0.1, 1e-12);
  EXPECT_NEAR(find(0, 2).rotation_deg, 5.0, 1e-9);
  EXPECT_TRUE(find(1, 2).loop);
  EXPECT_FALSE(find(0, 3).loop);
  EXPECT_FALSE(find(0, 4).loop);
  EXPECT_NEAR(find(0, 4).rotation_deg, 45.0, 1e-9);
  int loops = 0;
  for (const auto& pair : pairs) loops += pair.loop ? 1 : 0;
  EXPECT_EQ(loops, 2);
}

TEST(LoopGroundTruth, RelativeTranslationIsInTheFirstCameraFrame) {
  // Both cameras at distance 0.2 m of each other, whatever their common rotation.
  const std::vector<core::StampedPose> poses = {poseAt(0.0, 1.0, 90.0), poseAt(9.0, 1.2, 90.0)};
  const auto pairs = loopPairs(poses, {});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_NEAR(pairs[0].translation_m, 0.2, 1e-12);
  EXPECT_NEAR(pairs[0].rotation_deg, 0.0, 1e-6);
  EXPECT_TRUE(pairs[0].loop);
}

}  // namespace
}  // namespace segslam::eval
