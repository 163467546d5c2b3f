#include "segslam/synth/primitives.h"

#include <gtest/gtest.h>

namespace segslam::synth {
namespace {

TEST(SynthPrimitives, BoxFacesPointOutwardsAndCoverTheBox) {
  const Eigen::Vector3d low(1.0, 2.0, 3.0);
  const Eigen::Vector3d high(1.5, 2.25, 4.0);
  const Eigen::Vector3d centre = 0.5 * (low + high);
  double area = 0.0;
  for (const Rect& face : boxFaces(low, high)) {
    const Eigen::Vector3d face_centre =
        face.origin + 0.5 * (face.size_u * face.axis_u + face.size_v * face.axis_v);
    EXPECT_GT(face.normal().dot(face_centre - centre), 0.0);
    EXPECT_NEAR(face.normal().norm(), 1.0, 1e-12);
    for (const auto& corner : face.corners()) {
      EXPECT_TRUE((corner.array() >= low.array() - 1e-12).all());
      EXPECT_TRUE((corner.array() <= high.array() + 1e-12).all());
    }
    area += face.size_u * face.size_v;
  }
  EXPECT_NEAR(area, 2 * (0.5 * 0.25 + 0.5 * 1.0 + 0.25 * 1.0), 1e-12);
}

TEST(SynthPrimitives, FlippedRectCoversTheSameAreaFacingTheOtherWay) {
  const Rect rect{{0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 2.0, 1.0};
  const Rect back = flipped(rect);
  EXPECT_TRUE(back.normal().isApprox(-rect.normal()));
  EXPECT_TRUE(back.corners()[1].isApprox(rect.corners()[0]));
  EXPECT_TRUE(back.corners()[2].isApprox(rect.corners()[3]));
}

TEST(SynthPrimitives, LimbSpansItsEndsAndTransformsRigidly) {
  const Eigen::Vector3d a(0.0, 0.0, 1.0);
  const Eigen::Vector3d b(0.3, 0.0, 0.6);
  const Ellipsoid limb = limbBetween(a, b, 0.05, 0.01);
  EXPECT_TRUE(limb.center.isApprox(0.5 * (a + b)));
  EXPECT_NEAR(limb.radii.z(), 0.25 + 0.01, 1e-12);
  EXPECT_TRUE(limb.axes.col(2).isApprox((b - a).normalized()));
  EXPECT_TRUE((limb.axes.transpose() * limb.axes).isIdentity(1e-12));
  EXPECT_NEAR(limb.axes.determinant(), 1.0, 1e-12);
  geometry::Pose pose = geometry::Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(1, 2, 3);
  const Ellipsoid moved = transformed(pose, limb);
  EXPECT_TRUE(moved.center.isApprox(pose * limb.center));
  EXPECT_TRUE(moved.axes.isApprox(pose.linear() * limb.axes));
  EXPECT_TRUE(moved.radii.isApprox(limb.radii));
}

}  // namespace
}  // namespace segslam::synth
