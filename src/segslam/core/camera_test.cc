#include "segslam/core/camera.h"

#include <gtest/gtest.h>

namespace segslam::core {
namespace {

TEST(Camera, BackProjectionInvertsProjection) {
  Camera camera;
  camera.fx = 517.3;
  camera.fy = 516.5;
  camera.cx = 318.6;
  camera.cy = 255.3;
  const Eigen::Vector3d p = camera.backProject(100.25, 400.5, 2.5);
  EXPECT_DOUBLE_EQ(p.z(), 2.5);
  EXPECT_NEAR((camera.project(p) - Eigen::Vector2d(100.25, 400.5)).norm(), 0.0, 1e-9);
  EXPECT_FALSE(camera.hasDistortion());
  camera.distortion[4] = 0.1;
  EXPECT_TRUE(camera.hasDistortion());
}

}  // namespace
}  // namespace segslam::core
