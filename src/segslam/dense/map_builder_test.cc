#include "segslam/dense/map_builder.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace segslam::dense {
namespace {

core::Camera builderCamera() {
  core::Camera camera;
  camera.width = 32;
  camera.height = 24;
  camera.fx = camera.fy = 40.0;
  camera.cx = 15.5;
  camera.cy = 11.5;
  return camera;
}

KeyFrameImages flatView(const core::Camera& camera, float depth, std::uint8_t grey) {
  KeyFrameImages images;
  images.bgr = cv::Mat(camera.height, camera.width, CV_8UC3, cv::Scalar::all(grey));
  images.depth = cv::Mat(camera.height, camera.width, CV_32FC1, cv::Scalar(depth));
  return images;
}

MapBuilderOptions testOptions() {
  MapBuilderOptions options;
  options.keyframe.voxel_size = 0.005;
  options.cleaning.outlier_neighbours = 0;
  return options;
}

geometry::Pose translation(double x, double y, double z) {
  geometry::Pose pose = geometry::Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

TEST(MapBuilder, TwoKeyFramesArePlacedByTheirPoses) {
  const auto camera = builderCamera();
  MapBuilder builder(camera, testOptions());
  builder.addKeyFrame(0, 1.0, flatView(camera, 1.0f, 50));
  builder.addKeyFrame(1, 2.0, flatView(camera, 1.0f, 200));
  core::Trajectory poses;
  poses.append(1.0, translation(0.0, 0.0, 0.0));
  poses.append(2.0, translation(10.0, 0.0, 5.0));  // far apart: the views do not overlap
  const DenseMap map = builder.build(poses);
  EXPECT_EQ(builder.numKeyFrames(), 2u);
  ASSERT_GT(map.static_points.size(), 100u);
  std::size_t first = 0;
  std::size_t second = 0;
  for (std::size_t i = 0; i < map.static_points.size(); ++i) {
    const Eigen::Vector3f& p = map.static_points.points[i];
    if (map.static_points.colours[i][0] == 50) {
      ++first;
      EXPECT_NEAR(p.z(), 1.0f, 1e-4f);
      EXPECT_LT(std::abs(p.x()), 0.41f);
    } else {
      ++second;
      EXPECT_EQ(map.static_points.colours[i][0], 200);
      EXPECT_NEAR(p.z(), 6.0f, 1e-4f);
      EXPECT_NEAR(p.x(), 10.0f, 0.41f);
    }
  }
  EXPECT_EQ(first, second);
  EXPECT_TRUE(map.dynamic_points.empty());
  EXPECT_DOUBLE_EQ(map.voxel_size, 0.005);
}

TEST(MapBuilder, KeyFramesWithoutPoseAreLeftOutAndRebuildsFollowNewPoses) {
  const auto camera = builderCamera();
  MapBuilder builder(camera, testOptions());
  builder.addKeyFrame(0, 1.0, flatView(camera, 1.0f, 50));
  builder.addKeyFrame(1, 2.0, flatView(camera, 1.0f, 200));
  core::Trajectory only_first;
  only_first.append(1.0, translation(0.0, 0.0, 0.0));
  const auto culled = builder.build(only_first);
  for (const auto& colour : culled.static_points.colours) EXPECT_EQ(colour[0], 50);

  core::Trajectory corrected;
  corrected.append(1.0, translation(0.0, 0.0, 3.0));
  const auto moved = builder.build(corrected);
  ASSERT_EQ(moved.static_points.size(), culled.static_points.size());
  for (const auto& p : moved.static_points.points) EXPECT_NEAR(p.z(), 4.0f, 1e-4f);
}

TEST(MapBuilder, BadImagesSurfaceAsErrors) {
  const auto camera = builderCamera();
  MapBuilder builder(camera, testOptions());
  auto images = flatView(camera, 1.0f, 50);
  images.bgr = cv::Mat(3, 3, CV_8UC3);
  builder.addKeyFrame(0, 1.0, images);
  EXPECT_THROW(builder.finish(), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::dense
