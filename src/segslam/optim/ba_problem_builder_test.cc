#include "segslam/optim/ba_problem_builder.h"

#include <gtest/gtest.h>

namespace segslam::optim {
namespace {

TEST(BundleAdjustProblemBuilder, GivesEachIdOneSlot) {
  StereoIntrinsics intrinsics;
  intrinsics.bf = 30.0;
  BaProblemBuilder builder(intrinsics);
  geometry::Pose moved = geometry::Pose::Identity();
  moved.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);

  EXPECT_EQ(builder.addKeyFrame(7, geometry::Pose::Identity(), false), 0u);
  EXPECT_EQ(builder.addKeyFrame(3, moved, true), 1u);
  EXPECT_EQ(builder.addKeyFrame(7, moved, true), 0u);  // first pose and flag stay
  EXPECT_EQ(builder.addPoint(42, {0.0, 0.0, 2.0}), 0u);
  EXPECT_EQ(builder.addPoint(42, {9.0, 9.0, 9.0}), 0u);
  builder.addObservation(1, 0, RgbdObservation{});

  EXPECT_EQ(builder.keyFrameIndex(3), 1u);
  EXPECT_FALSE(builder.keyFrameIndex(5).has_value());
  EXPECT_EQ(builder.pointIndex(42), 0u);
  const BundleAdjustmentProblem& problem = builder.problem();
  ASSERT_EQ(problem.keyframes.size(), 2u);
  EXPECT_FALSE(problem.keyframes[0].fixed);
  EXPECT_TRUE(problem.keyframes[0].T_cw.isApprox(geometry::Pose::Identity()));
  ASSERT_EQ(problem.points.size(), 1u);
  EXPECT_EQ(problem.points[0].position, Eigen::Vector3d(0.0, 0.0, 2.0));
  ASSERT_EQ(problem.observations.size(), 1u);
  EXPECT_EQ(problem.observations[0].keyframe, 1u);
}

TEST(BundleAdjustProblemBuilder, TakeEmptiesTheBuilderButKeepsTheIntrinsics) {
  StereoIntrinsics intrinsics;
  intrinsics.fx = 600.0;
  BaProblemBuilder builder(intrinsics);
  builder.addKeyFrame(1, geometry::Pose::Identity(), true);
  const BundleAdjustmentProblem taken = builder.take();
  EXPECT_EQ(taken.keyframes.size(), 1u);
  EXPECT_EQ(taken.intrinsics.fx, 600.0);
  EXPECT_TRUE(builder.problem().keyframes.empty());
  EXPECT_FALSE(builder.keyFrameIndex(1).has_value());
  EXPECT_EQ(builder.problem().intrinsics.fx, 600.0);
  EXPECT_EQ(builder.addKeyFrame(1, geometry::Pose::Identity(), true), 0u);
}

}  // namespace
}  // namespace segslam::optim
