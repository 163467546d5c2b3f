#include "segslam/dense/keyframe_fold.h"

#include <gtest/gtest.h>

namespace segslam::dense {
namespace {

Eigen::Isometry3d at(double x, double y, double z, double yaw = 0.0) {
  Eigen::Isometry3d pose(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()));
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

TEST(KeyFrameFold, TheNearestViewIsNearAndLooksTheSameWay) {
  const std::vector<Eigen::Isometry3d> candidates = {at(0.0, 0.0, 0.0, M_PI), at(0.4, 0.0, 0.0),
                                                     at(3.0, 0.0, 0.0)};
  // The first stands on the spot but looks back: the second, 0.4 m away, sees the same.
  EXPECT_EQ(nearestView(at(0.0, 0.0, 0.0), candidates), 1u);
  EXPECT_EQ(nearestView(at(2.8, 0.0, 0.0), candidates), 2u);
}

TEST(KeyFrameFold, PointsMoveIntoTheOtherCameraAndShareItsVoxels) {
  KeyFrameCloud into;  // camera 0.2 m right of the other
  into.static_points.add({0.0f, 0.0f, 1.0f}, {10, 10, 10});
  KeyFrameCloud from;
  from.static_points.add({0.2f, 0.0f, 1.0f}, {30, 30, 30});  // the same point, seen from the left
  from.static_points.add({0.1f, 0.0f, 1.0f}, {50, 50, 50});
  from.dynamic_points.add({0.0f, 0.0f, 2.0f}, {1, 2, 3}, 8);
  const KeyFrameCloud folded = foldInto(into, at(0.2, 0.0, 0.0), from, at(0.0, 0.0, 0.0), 0.01);
  ASSERT_EQ(folded.static_points.size(), 2u);
  ASSERT_EQ(folded.dynamic_points.size(), 1u);
  EXPECT_TRUE(folded.dynamic_points.points[0].isApprox(Eigen::Vector3f(-0.2f, 0.0f, 2.0f)));
  EXPECT_EQ(folded.dynamic_points.labels[0], 8);
  for (std::size_t i = 0; i < 2; ++i) {
    const Eigen::Vector3f& p = folded.static_points.points[i];
    if (folded.static_points.colours[i][0] == 50) {
      EXPECT_TRUE(p.isApprox(Eigen::Vector3f(-0.1f, 0.0f, 1.0f), 1e-5f));
    } else {
      EXPECT_EQ(folded.static_points.colours[i][0], 20);  // the mean of the two views
      EXPECT_TRUE(p.isApprox(Eigen::Vector3f(0.0f, 0.0f, 1.0f), 1e-5f));
    }
  }
}

}  // namespace
}  // namespace segslam::dense
