#include "segslam/synth/renderer.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

namespace segslam::synth {
namespace {

core::Camera renderCamera() {
  core::Camera camera;
  camera.width = 80;
  camera.height = 60;
  camera.fx = camera.fy = 70.0;
  camera.cx = 39.5;
  camera.cy = 29.5;
  return camera;
}

const Texture& greyTexture() {
  static const Texture texture(cv::Mat(8, 8, CV_8UC3, cv::Scalar(200, 150, 100)), 0.1);
  return texture;
}

// A 20 m square in the plane z = distance of the camera frame (camera at the identity), facing it.
TexturedRect wallAt(double distance, std::uint16_t instance) {
  Rect rect{
      {10.0, -10.0, distance}, -Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 20.0, 20.0};
  return {rect, {&greyTexture(), instance, core::SemanticClass::kWall, false}};
}

std::uint16_t depthAt(const FrameImages& images, int u, int v) {
  return images.depth.at<std::uint16_t>(v, u);
}

TEST(SynthRenderer, FrontoParallelWallHasExactQuantisedDepth) {
  RenderScene scene;
  scene.rects.push_back(wallAt(2.0, 3));
  const auto images =
      renderFrame(scene, renderCamera(), geometry::Pose::Identity(), DepthNoise::kNone, 1);
  ASSERT_EQ(images.depth.type(), CV_16UC1);
  ASSERT_EQ(images.rgb.type(), CV_8UC3);
  for (int v = 0; v < 60; ++v) {
    for (int u = 0; u < 80; ++u) {
      ASSERT_EQ(depthAt(images, u, v), 10000);
      ASSERT_EQ(images.instances.at<std::uint16_t>(v, u), 3);
      ASSERT_EQ(images.labels.at<std::uint8_t>(v, u),
                static_cast<std::uint8_t>(core::SemanticClass::kWall));
      ASSERT_EQ(images.mask.at<std::uint8_t>(v, u), 0);
    }
  }
  EXPECT_GT(images.rgb.at<cv::Vec3b>(30, 40)[0], 100);
}

TEST(SynthRenderer, BackSidesAreInvisible) {
  RenderScene scene;
  scene.rects.push_back({flipped(wallAt(2.0, 3).shape), wallAt(2.0, 3).surface});
  const auto images =
      renderFrame(scene, renderCamera(), geometry::Pose::Identity(), DepthNoise::kNone, 1);
  EXPECT_EQ(cv::countNonZero(images.depth), 0);
  EXPECT_EQ(cv::countNonZero(images.instances), 0);
}

TEST(SynthRenderer, SlantedPlaneDepthIsTheRayIntersection) {
  // The floor 1.2 m below a camera pitched down by 20 degrees.
  const double pitch = 20.0 * std::numbers::pi / 180.0;
  geometry::Pose T_wc = geometry::Pose::Identity();
  T_wc.linear() = Eigen::AngleAxisd(-pitch, Eigen::Vector3d::UnitX()).toRotationMatrix();
  RenderScene scene;
  // Axes x then z: the normal x cross z = -y points up, at the camera.
  scene.rects.push_back(
      {Rect{{-10.0, 1.2, -10.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), 20.0, 30.0},
       {&greyTexture(), 1, core::SemanticClass::kFloor, false}});
  const core::Camera camera = renderCamera();
  const auto images = renderFrame(scene, camera, T_wc, DepthNoise::kNone, 1);
  int checked = 0;
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const Eigen::Vector3d ray_w = T_wc.linear() * Eigen::Vector3d((u - camera.cx) / camera.fx,
                                                                    (v - camera.cy) / camera.fy, 1);
      if (ray_w.y() <= 1e-6) {
        EXPECT_EQ(depthAt(images, u, v), 0);
        continue;
      }
      const double z = 1.2 / ray_w.y();  // ray length factor = depth along the optical axis
      if (z > 13.0) continue;
      EXPECT_EQ(depthAt(images, u, v), static_cast<int>(std::lround(z * 5000.0))) << u << "," << v;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(SynthRenderer, EllipsoidOccludesWallAndIsMaskedWhenDynamic) {
  RenderScene scene;
  scene.rects.push_back(wallAt(3.0, 1));
  Ellipsoid ball;
  ball.center = {0.0, 0.0, 2.0};
  ball.radii = {0.3, 0.3, 0.3};
  scene.ellipsoids.push_back({ball, {&greyTexture(), 7, core::SemanticClass::kPerson, true}});
  const auto images =
      renderFrame(scene, renderCamera(), geometry::Pose::Identity(), DepthNoise::kNone, 1);
  // The centre ray (between the four centre pixels) hits at z = 1.7; the pixels next to it nearly.
  EXPECT_NEAR(depthAt(images, 39, 29) / 5000.0, 1.7, 0.002);
  EXPECT_EQ(images.instances.at<std::uint16_t>(29, 39), 7);
  EXPECT_EQ(images.mask.at<std::uint8_t>(29, 39), 255);
  EXPECT_EQ(images.instances.at<std::uint16_t>(0, 0), 1);
  EXPECT_EQ(images.mask.at<std::uint8_t>(0, 0), 0);
  // Radius 0.3 at 2 m covers about 70 * 0.3 / 2 = 10.5 pixels around the centre.
  const int ball_pixels = cv::countNonZero(images.mask);
  EXPECT_NEAR(ball_pixels, std::numbers::pi * 10.6 * 10.6, 40.0);
}

TEST(SynthRenderer, ResultDoesNotDependOnTheNumberOfThreads) {
  RenderScene scene;
  scene.rects.push_back(wallAt(3.0, 1));
  Ellipsoid ball;
  ball.center = {0.2, -0.1, 2.0};
  ball.radii = {0.3, 0.5, 0.2};
  scene.ellipsoids.push_back({ball, {&greyTexture(), 7, core::SemanticClass::kPerson, true}});
  const auto parallel =
      renderFrame(scene, renderCamera(), geometry::Pose::Identity(), DepthNoise::kKinect, 5);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const auto serial =
      renderFrame(scene, renderCamera(), geometry::Pose::Identity(), DepthNoise::kKinect, 5);
  EXPECT_EQ(cv::norm(parallel.rgb, serial.rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(parallel.depth, serial.depth, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(parallel.mask, serial.mask, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace segslam::synth
