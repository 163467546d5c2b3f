#include "segslam/map/map_snapshot.h"

#include <gtest/gtest.h>

namespace segslam::map {
namespace {

std::shared_ptr<const FrameCamera> testCamera() {
  core::Camera camera;
  camera.width = 320;
  camera.height = 240;
  camera.fx = camera.fy = 262.5;
  camera.cx = 159.5;
  camera.cy = 119.5;
  return std::make_shared<FrameCamera>(camera, kDefaultVirtualBaselineM, 40.0,
                                       feature::ScaleLevels(8, 1.2));
}

Frame gridFrame(std::uint64_t id, const std::shared_ptr<const FrameCamera>& camera, double x) {
  std::vector<cv::KeyPoint> keypoints;
  for (int i = 0; i < 40; ++i) {
    keypoints.emplace_back(20.0f + 7.0f * static_cast<float>(i),
                           30.0f + 4.0f * static_cast<float>(i), 31.0f, 0.0f, 1.0f, i % 3);
  }
  cv::Mat descriptors(40, 32, CV_8U);
  cv::randu(descriptors, 0, 255);
  const cv::Mat depth(240, 320, CV_32F, cv::Scalar(2.0));
  Frame frame(id, 0.1 * static_cast<double>(id), keypoints, descriptors, depth, {}, camera);
  frame.T_cw.translation() = Eigen::Vector3d(x, 0.0, 0.0);
  return frame;
}

// Three keyframes sharing points (the last two more than 15), as tracking and local mapping
// leave them: covisibility, spanning tree, a culled keyframe and a culled point.
void buildMap(Map& map, const std::shared_ptr<const FrameCamera>& camera) {
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
  for (std::uint64_t k = 0; k < 4; ++k) {
    keyframes.push_back(map.createKeyFrame(gridFrame(k, camera, -0.05 * static_cast<double>(k))));
  }
  for (std::size_t i = 0; i < 40; ++i) {
    auto point = map.createMapPoint(keyframes[0]->unproject(i), keyframes[0].get());
    for (std::size_t k = 0; k < keyframes.size(); ++k) {
      if (k == 1 && i >= 10) continue;
      point->addObservation(keyframes[k].get(), i);
      keyframes[k]->addMapPoint(point, i);
    }
    point->updateDescriptor();
    point->updateNormalAndDepth();
    point->seen_through = static_cast<int>(i % 2);
  }
  for (const auto& keyframe : keyframes) keyframe->updateConnections();
  keyframes[2]->setBad();
  map.mapPoints()[7]->setBad();
}

TEST(MapSnapshot, ARestoredMapIsCapturedAsTheSameFile) {
  const auto camera = testCamera();
  Map original;
  buildMap(original, camera);
  MapSessions first_run;
  const auto saved = captureMap(original, first_run);
  ASSERT_EQ(saved.keyframes.size(), 3U);
  ASSERT_EQ(saved.points.size(), 39U);
  EXPECT_EQ(saved.keyframes[2].id, 3U);
  EXPECT_EQ(saved.keyframes[2].parent, 0U);

  Map restored;
  const MapSessions sessions = restoreMap(saved, camera, restored);
  EXPECT_EQ(sessions.current, 1U);
  EXPECT_EQ(restored.numKeyFrames(), 3U);
  EXPECT_EQ(restored.numMapPoints(), 39U);
  EXPECT_EQ(encodeMapFile(captureMap(restored, sessions)), encodeMapFile(saved));

  const auto keyframes = restored.keyFrames();
  EXPECT_EQ(keyframes[1]->parent, keyframes[0].get());
  EXPECT_EQ(keyframes[2]->weight(keyframes[0].get()), 40);
  EXPECT_EQ(keyframes[2]->mapPoints()[5]->id, 5U);
  EXPECT_EQ(keyframes[2]->mapPoints()[5]->seen_through, 1);
}

TEST(MapSnapshot, WhatTheNextSessionMakesContinuesTheIdsAndIsTaggedWithIt) {
  const auto camera = testCamera();
  Map original;
  buildMap(original, camera);
  Map restored;
  const MapSessions sessions = restoreMap(captureMap(original, {}), camera, restored);
  const auto keyframe = restored.createKeyFrame(gridFrame(9, camera, 0.0));
  const auto point = restored.createMapPoint(Eigen::Vector3d(0, 0, 2), keyframe.get());
  point->addObservation(keyframe.get(), 0);
  keyframe->addMapPoint(point, 0);
  EXPECT_EQ(keyframe->id, 4U);
  EXPECT_EQ(point->id, 40U);
  const auto saved = captureMap(restored, sessions);
  EXPECT_EQ(saved.keyframes.back().session, 1U);
  EXPECT_EQ(saved.keyframes.front().session, 0U);
  EXPECT_EQ(saved.points.back().session, 1U);
}

TEST(MapSnapshot, RestoringIntoAMapInUseIsAnError) {
  const auto camera = testCamera();
  Map original;
  buildMap(original, camera);
  EXPECT_THROW(restoreMap(captureMap(original, {}), camera, original), std::logic_error);
}

}  // namespace
}  // namespace segslam::map
