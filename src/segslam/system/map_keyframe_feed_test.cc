#include "segslam/system/map_keyframe_feed.h"

#include <gtest/gtest.h>

#include "segslam/dense/dense_test_scene.h"

namespace segslam::system {
namespace {

using dense::test_scene::smallCamera;

// A grey wall 1 m away, with a mask that marks nothing.
dense::KeyFrameImages flatWall(const core::Camera& camera) {
  dense::KeyFrameImages images = dense::test_scene::flatView(camera, 1.0f, 128);
  images.dynamic_mask = cv::Mat::zeros(camera.height, camera.width, CV_8UC1);
  return images;
}

dense::MapBuilderOptions builderOptions() {
  dense::MapBuilderOptions options;
  options.keyframe.voxel_size = 0.005;
  options.keyframe.mask_dilation_px = 0;
  options.cleaning.outlier_neighbours = 0;
  return options;
}

core::Trajectory keyFramesAt(const std::vector<double>& timestamps) {
  core::Trajectory trajectory;
  for (double t : timestamps) trajectory.append(t, geometry::Pose::Identity());
  return trajectory;
}

// The left half of the image moves, as the keyframe's own network output shows.
segmentation::LateOutput ownOutput(std::uint64_t frame_id, const core::Camera& camera) {
  segmentation::LateOutput output;
  output.frame_id = frame_id;
  output.keyframe = true;
  output.dynamic = cv::Mat::zeros(camera.height, camera.width, CV_8UC1);
  output.dynamic(cv::Rect(0, 0, camera.width / 2, camera.height)) = 255;
  return output;
}

TEST(MapKeyFrameFeed, AKeyFrameGoesToTheMapWithItsOwnMaskAdded) {
  const core::Camera camera = smallCamera();
  dense::MapBuilder builder(camera, builderOptions());
  MapKeyFrameFeed feed(builder, true);
  feed.addKeyFrame(10, 1.0, flatWall(camera));
  EXPECT_EQ(builder.numKeyFrames(), 0u) << "held until its own mask comes";
  feed.addOwnMask(ownOutput(10, camera));
  EXPECT_EQ(builder.numKeyFrames(), 1u);
  const auto map = builder.build(keyFramesAt({1.0}));
  ASSERT_FALSE(map.static_points.empty());
  ASSERT_FALSE(map.dynamic_points.empty());
  for (const auto& point : map.static_points.points) EXPECT_GT(point.x(), 0.0) << "right half";
}

TEST(MapKeyFrameFeed, AKeyFrameWhoseMaskDoesNotComeGoesAsItIsAfterTheWait) {
  const core::Camera camera = smallCamera();
  dense::MapBuilder builder(camera, builderOptions());
  MapKeyFrameFeed feed(builder, true, 5);
  feed.addKeyFrame(10, 1.0, flatWall(camera));
  feed.setTrackedFrame(14);
  EXPECT_EQ(builder.numKeyFrames(), 0u);
  feed.setTrackedFrame(15);
  EXPECT_EQ(builder.numKeyFrames(), 1u);
  feed.addOwnMask(ownOutput(10, camera));  // too late: nothing happens
  EXPECT_TRUE(builder.build(keyFramesAt({1.0})).dynamic_points.empty());
}

TEST(MapKeyFrameFeed, FlushingOrNotWaitingHandsKeyFramesOverAtOnce) {
  const core::Camera camera = smallCamera();
  dense::MapBuilder builder(camera, builderOptions());
  MapKeyFrameFeed waiting(builder, true);
  waiting.addKeyFrame(10, 1.0, flatWall(camera));
  waiting.flush();
  EXPECT_EQ(builder.numKeyFrames(), 1u);
  MapKeyFrameFeed immediate(builder, false);
  immediate.addKeyFrame(11, 2.0, flatWall(camera));
  EXPECT_EQ(builder.numKeyFrames(), 2u);
}

}  // namespace
}  // namespace segslam::system
