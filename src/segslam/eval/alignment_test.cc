#include "segslam/eval/alignment.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>
#include <random>

namespace segslam::eval {
namespace {

Eigen::Matrix3Xd randomPoints(int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  Eigen::Matrix3Xd points(3, count);
  for (int k = 0; k < count; ++k) {
    points.col(k) = Eigen::Vector3d(coordinate(rng), coordinate(rng), coordinate(rng));
  }
  return points;
}

Eigen::Matrix3d knownRotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).matrix();
}

double largestError(const Alignment& alignment, const Eigen::Matrix3Xd& source,
                    const Eigen::Matrix3Xd& target) {
  double largest = 0.0;
  for (int k = 0; k < source.cols(); ++k) {
    largest =
        std::max(largest, (alignment.apply(Eigen::Vector3d(source.col(k))) - target.col(k)).norm());
  }
  return largest;
}

TEST(Alignment, Se3RecoversAKnownRigidTransform) {
  const auto source = randomPoints(50);
  const Eigen::Vector3d t(0.3, -1.2, 2.0);
  const Eigen::Matrix3Xd target = (knownRotation() * source).colwise() + t;
  const auto alignment = alignPoints(source, target, AlignmentMethod::kSe3);
  EXPECT_TRUE(alignment.rotation.isApprox(knownRotation(), 1e-12));
  EXPECT_TRUE(alignment.translation.isApprox(t, 1e-12));
  EXPECT_DOUBLE_EQ(alignment.scale, 1.0);
  EXPECT_LT(largestError(alignment, source, target), 1e-12);
}

TEST(Alignment, InverseUndoesASimilarity) {
  const Alignment alignment{knownRotation(), Eigen::Vector3d(0.3, -1.2, 4.0), 2.5};
  const Eigen::Vector3d point(0.7, 0.1, -3.0);
  EXPECT_TRUE(alignment.inverse().apply(alignment.apply(point)).isApprox(point, 1e-12));
  EXPECT_TRUE((alignment.inverse().matrix() * alignment.matrix())
                  .isApprox(Eigen::Matrix4d::Identity(), 1e-12));
}

TEST(Alignment, Sim3RecoversAKnownSimilarity) {
  const auto source = randomPoints(50);
  const Eigen::Vector3d t(-0.5, 0.1, 0.9);
  const Eigen::Matrix3Xd target = (2.5 * knownRotation() * source).colwise() + t;
  const auto alignment = alignPoints(source, target, AlignmentMethod::kSim3);
  EXPECT_NEAR(alignment.scale, 2.5, 1e-12);
  EXPECT_TRUE(alignment.rotation.isApprox(knownRotation(), 1e-12));
  EXPECT_TRUE(alignment.translation.isApprox(t, 1e-12));
  EXPECT_LT(largestError(alignment, source, target), 1e-12);
  // SE(3) cannot absorb the scale.
  EXPECT_GT(largestError(alignPoints(source, target, AlignmentMethod::kSe3), source, target), 0.1);
}

TEST(Alignment, PointsAlignedToThemselvesGiveTheIdentity) {
  const auto points = randomPoints(20);
  const auto alignment = alignPoints(points, points, AlignmentMethod::kSe3);
  EXPECT_TRUE(alignment.matrix().isApprox(Eigen::Matrix4d::Identity(), 1e-12));
  EXPECT_LT(largestError(alignment, points, points), 1e-12);
}

TEST(Alignment, NoneLeavesThePointsAlone) {
  const auto source = randomPoints(5);
  const Eigen::Matrix3Xd target = source.colwise() + Eigen::Vector3d(1.0, 0.0, 0.0);
  const auto alignment = alignPoints(source, target, AlignmentMethod::kNone);
  EXPECT_TRUE(alignment.matrix().isIdentity());
}

TEST(Alignment, MirroredPointsStillGetAProperRotation) {
  const auto source = randomPoints(30);
  Eigen::Matrix3Xd target = source;
  target.row(2) *= -1.0;
  const auto alignment = alignPoints(source, target, AlignmentMethod::kSe3);
  EXPECT_NEAR(alignment.rotation.determinant(), 1.0, 1e-12);
}

TEST(Alignment, AppliesToPosesAndHasAMatrix) {
  Alignment alignment;
  alignment.rotation = Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ()).matrix();
  alignment.translation = Eigen::Vector3d(1.0, 2.0, 3.0);
  alignment.scale = 2.0;
  geometry::Pose pose = geometry::Pose::Identity();
  pose.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  const auto aligned = alignment.apply(pose);
  EXPECT_TRUE(aligned.translation().isApprox(Eigen::Vector3d(1.0, 4.0, 3.0), 1e-12));
  EXPECT_TRUE(aligned.linear().isApprox(alignment.rotation, 1e-12));
  const Eigen::Vector4d mapped = alignment.matrix() * Eigen::Vector4d(1.0, 0.0, 0.0, 1.0);
  EXPECT_TRUE(mapped.head<3>().isApprox(aligned.translation(), 1e-12));
}

TEST(Alignment, MethodNamesRoundTrip) {
  for (const auto& name : alignmentMethodNames()) {
    const auto method = parseAlignmentMethod(name);
    ASSERT_TRUE(method.has_value());
    EXPECT_EQ(alignmentMethodName(*method), name);
  }
  EXPECT_FALSE(parseAlignmentMethod("affine").has_value());
}

}  // namespace
}  // namespace segslam::eval
