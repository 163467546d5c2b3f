#include "segslam/dense/labelled_cloud.h"

#include <gtest/gtest.h>

namespace segslam::dense {
namespace {

TEST(LabelledCloud, VoxelDownsampleAveragesAndVotes) {
  LabelledCloud cloud;
  cloud.add({0.01f, 0.01f, 0.01f}, {0, 0, 0}, 5, 1);
  cloud.add({0.03f, 0.03f, 0.03f}, {100, 50, 20}, 5, 2);
  cloud.add({0.05f, 0.05f, 0.05f}, {200, 100, 40}, 5, 2);
  cloud.add({0.07f, 0.07f, 0.07f}, {20, 20, 20}, 7, 3);
  cloud.add({1.05f, 0.05f, 0.05f}, {9, 9, 9}, 2, 0);
  const auto down = voxelDownsample(cloud, 0.5);
  ASSERT_EQ(down.size(), 2u);
  const std::size_t near = down.points[0].x() < 0.5f ? 0 : 1;
  EXPECT_TRUE(down.points[near].isApprox(Eigen::Vector3f::Constant(0.04f), 1e-5f));
  EXPECT_EQ(down.colours[near], (Rgb{80, 43, 20}));  // means rounded
  EXPECT_EQ(down.labels[near], 5);
  EXPECT_EQ(down.instances[near], 2);
  EXPECT_EQ(down.labels[1 - near], 2);
}

TEST(LabelledCloud, TransformMovesPoints) {
  LabelledCloud cloud;
  cloud.add({1.0f, 0.0f, 0.0f}, {1, 2, 3}, 4, 5);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.0, 0.0, 2.0);
  const auto moved = transformed(cloud, T);
  EXPECT_TRUE(moved.points[0].isApprox(Eigen::Vector3f(0.0f, 1.0f, 2.0f), 1e-6f));
  EXPECT_EQ(moved.labels[0], 4);
  EXPECT_EQ(moved.instances[0], 5);
}

}  // namespace
}  // namespace segslam::dense
