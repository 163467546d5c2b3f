#include "segslam/synth/camera_path.h"

#include <gtest/gtest.h>

#include <iostream>
#include <numbers>

#include "segslam/synth/room_layout.h"

namespace segslam::synth {
namespace {

constexpr double kMaxSpeed = 0.4;                               // m/s
constexpr double kMaxTurnRate = 30.0 * std::numbers::pi / 180;  // rad/s

SynthOptions pathOptions(const std::string& path, int frames) {
  SynthOptions options;
  options.path = path;
  options.frames = frames;
  return options;
}

void expectHandheldAndInside(const std::vector<geometry::Pose>& poses) {
  Eigen::AlignedBox3d inside = roomBox();
  inside.min().array() += 0.3;
  inside.max().array() -= 0.3;
  double top_speed = 0.0;
  double top_turn = 0.0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    ASSERT_TRUE(inside.contains(poses[k].translation())) << "frame " << k;
    ASSERT_TRUE(poses[k].linear().isUnitary(1e-9)) << "frame " << k;
    ASSERT_NEAR(poses[k].linear().determinant(), 1.0, 1e-9);
    if (k == 0) continue;
    const geometry::Pose step = poses[k - 1].inverse() * poses[k];
    top_speed = std::max(top_speed, step.translation().norm() * kSynthFps);
    top_turn = std::max(top_turn, geometry::rotationAngleAccurate(step) * kSynthFps);
  }
  EXPECT_LE(top_speed, kMaxSpeed);
  EXPECT_LE(top_turn, kMaxTurnRate);
  std::cout << "top speed " << top_speed << " m/s, top turn rate "
            << top_turn * 180 / std::numbers::pi << " deg/s\n";
}

TEST(SynthCameraPath, XyzMovesAlongAllThreeCameraAxesAtHandheldSpeed) {
  const auto poses = cameraTrajectory(pathOptions("xyz", 400));
  ASSERT_EQ(poses.size(), 400u);
  expectHandheldAndInside(poses);
  // Offsets from the start in the start camera's frame reach +-10 cm along each axis.
  Eigen::Vector3d low = Eigen::Vector3d::Zero();
  Eigen::Vector3d high = Eigen::Vector3d::Zero();
  for (const auto& pose : poses) {
    const Eigen::Vector3d offset =
        poses[0].linear().transpose() * (pose.translation() - poses[0].translation());
    low = low.cwiseMin(offset);
    high = high.cwiseMax(offset);
  }
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_LT(low[axis], -0.1) << "axis " << axis;
    EXPECT_GT(high[axis], 0.1) << "axis " << axis;
  }
}

TEST(SynthCameraPath, LoopEndsExactlyAtItsStartAndGoesSomewhereElse) {
  for (int frames : {kSynthMinLoopFrames, 300, 901}) {
    const auto poses = cameraTrajectory(pathOptions("loop", frames));
    ASSERT_EQ(poses.size(), static_cast<std::size_t>(frames));
    EXPECT_LT((poses.front().matrix() - poses.back().matrix()).cwiseAbs().maxCoeff(), 1e-9);
    expectHandheldAndInside(poses);
    const geometry::Pose half = poses.front().inverse() * poses[frames / 2];
    EXPECT_GT(half.translation().norm(), 0.8);
    EXPECT_GT(geometry::rotationAngle(half), 60.0 * std::numbers::pi / 180);
  }
}

TEST(SynthCameraPath, RoomLoopTurnsOnceAndEndsAtItsStart) {
  const int frames = 600;
  const auto poses = cameraTrajectory(pathOptions("room", frames));
  EXPECT_LT((poses.front().matrix() - poses.back().matrix()).cwiseAbs().maxCoeff(), 1e-9);
  expectHandheldAndInside(poses);
  const geometry::Pose half = poses.front().inverse() * poses[frames / 2];
  EXPECT_GT(geometry::rotationAngle(half), 170.0 * std::numbers::pi / 180);
}

TEST(SynthCameraPath, RoomLapsRepeatTheCircuit) {
  SynthOptions options = pathOptions("room", 1201);
  options.laps = 2;
  const auto poses = cameraTrajectory(options);
  for (int k : {0, 600, 1200}) EXPECT_TRUE(poses[k].isApprox(poses.front(), 1e-9)) << k;
  EXPECT_TRUE(poses[100].isApprox(poses[700], 1e-9));
  expectHandheldAndInside(poses);
}

TEST(SynthCameraPath, StaticNeverMoves) {
  const auto poses = cameraTrajectory(pathOptions("static", 50));
  for (const auto& pose : poses) EXPECT_TRUE(pose.isApprox(poses.front(), 0.0));
  expectHandheldAndInside(poses);
}

}  // namespace
}  // namespace segslam::synth
