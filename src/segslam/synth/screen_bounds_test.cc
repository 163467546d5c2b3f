#include "segslam/synth/screen_bounds.h"

#include <gtest/gtest.h>

#include <array>

namespace segslam::synth {
namespace {

core::Camera boundsCamera() {
  core::Camera camera;
  camera.width = 100;
  camera.height = 80;
  camera.fx = camera.fy = 100.0;
  camera.cx = 49.5;
  camera.cy = 39.5;
  return camera;
}

TEST(SynthScreenBounds, QuadInFrontProjectsToItsPixelBox) {
  // Corners at z = 2 project to u = 49.5 + 50 * x, v = 39.5 + 50 * y.
  const std::array<Eigen::Vector3d, 4> quad{
      {{-0.2, -0.1, 2.0}, {0.2, -0.1, 2.0}, {0.2, 0.1, 2.0}, {-0.2, 0.1, 2.0}}};
  const PixelBox box = screenBounds(quad, quadEdges(), boundsCamera(), 0.01);
  EXPECT_EQ(box.u0, 39);
  EXPECT_EQ(box.u1, 60);
  EXPECT_EQ(box.v0, 34);
  EXPECT_EQ(box.v1, 45);
}

TEST(SynthScreenBounds, ClipsAtTheNearPlaneAndTheImage) {
  // A floor-like quad from behind the camera to far in front: clipped, not dropped.
  const std::array<Eigen::Vector3d, 4> floor{
      {{-1.0, 1.0, -1.0}, {1.0, 1.0, -1.0}, {1.0, 1.0, 5.0}, {-1.0, 1.0, 5.0}}};
  const PixelBox box = screenBounds(floor, quadEdges(), boundsCamera(), 0.01);
  EXPECT_EQ(box.u0, 0);
  EXPECT_EQ(box.u1, 99);
  EXPECT_EQ(box.v0, 59);  // the far edge at z = 5 is at v = 39.5 + 20
  EXPECT_EQ(box.v1, 79);
}

TEST(SynthScreenBounds, EmptyBehindTheCameraOrOutsideTheImage) {
  const std::array<Eigen::Vector3d, 4> behind{{{-1, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-1, 1, -2}}};
  EXPECT_TRUE(screenBounds(behind, quadEdges(), boundsCamera(), 0.01).empty());
  const std::array<Eigen::Vector3d, 4> aside{{{5, -1, 2}, {6, -1, 2}, {6, 1, 2}, {5, 1, 2}}};
  EXPECT_TRUE(screenBounds(aside, quadEdges(), boundsCamera(), 0.01).empty());
}

}  // namespace
}  // namespace segslam::synth
