#include "segslam/mapping/local_mapper.h"

#include <gtest/gtest.h>

#include "segslam/mapping/mapping_test_scene.h"

namespace segslam::mapping {
namespace {

using testing::addPoint;
using testing::maskOverKeypoints;
using testing::rowFrame;

// A keyframe made at frame 10, which made points at all its keypoints while a person stood over
// keypoints 0-5 unmasked; local mapping (synchronous) waits 5 frames for its own mask.
struct WaitingKeyFrame {
  map::Map map;
  LocalMapper mapper{map, options()};
  std::shared_ptr<map::KeyFrame> keyframe = map.createKeyFrame(rowFrame(10));
  std::vector<std::shared_ptr<map::MapPoint>> points;

  static LocalMapperOptions options() {
    LocalMapperOptions options;
    options.own_mask_wait_frames = 5;
    return options;
  }

  WaitingKeyFrame() {
    for (std::size_t i = 0; i < testing::kKeypoints; ++i) {
      points.push_back(addPoint(map, *keyframe, i));
    }
    mapper.insertKeyFrame(keyframe);
  }

  [[nodiscard]] int culled() const {
    return static_cast<int>(
        std::count_if(points.begin(), points.end(), [](const auto& point) { return point->bad; }));
  }
};

TEST(LocalMapper, AKeyFrameWaitsForItsOwnMaskThenCullsThePointsItMadeOnTheObject) {
  WaitingKeyFrame scene;
  scene.mapper.setTrackedFrame(13);
  scene.mapper.processQueued();
  EXPECT_EQ(scene.mapper.queuedKeyFrames(), 1u) << "its mask has not come";
  EXPECT_FALSE(scene.mapper.isIdle());
  scene.mapper.addKeyFrameMask(10, maskOverKeypoints(0, 6));
  scene.mapper.processQueued();
  EXPECT_EQ(scene.mapper.queuedKeyFrames(), 0u);
  EXPECT_EQ(scene.culled(), 6);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_TRUE(scene.points[i]->bad) << i;
  for (std::size_t i = 6; i < scene.points.size(); ++i) {
    EXPECT_FALSE(scene.points[i]->provisional) << "checked by its keyframe's mask";
  }
  const OwnMaskStats stats = scene.mapper.ownMaskStats();
  EXPECT_EQ(stats.keyframes_with_own_mask, 1);
  EXPECT_EQ(stats.points_culled, 6);
  EXPECT_DOUBLE_EQ(stats.mean_wait_frames, 3.0);
}

TEST(LocalMapper, AKeyFrameWhoseMaskDoesNotComeIsMappedAsItIsAfterTheWait) {
  WaitingKeyFrame scene;
  scene.mapper.setTrackedFrame(14);
  scene.mapper.processQueued();
  EXPECT_EQ(scene.mapper.queuedKeyFrames(), 1u);
  scene.mapper.setTrackedFrame(15);
  scene.mapper.processQueued();
  EXPECT_EQ(scene.mapper.queuedKeyFrames(), 0u);
  EXPECT_EQ(scene.culled(), 0);
  EXPECT_EQ(scene.mapper.ownMaskStats().keyframes_without, 1);
  // Too late now: the mask is dropped.
  scene.mapper.addKeyFrameMask(10, maskOverKeypoints(0, 6));
  scene.mapper.processQueued();
  EXPECT_EQ(scene.culled(), 0);
}

TEST(LocalMapper, FinishingMapsTheKeyFramesStillWaiting) {
  WaitingKeyFrame scene;
  scene.mapper.finish();
  scene.mapper.processQueued();
  EXPECT_EQ(scene.mapper.queuedKeyFrames(), 0u);
}

TEST(LocalMapper, OnItsOwnThreadAWaitingKeyFrameIsMappedWhenItsMaskComes) {
  WaitingKeyFrame scene;
  scene.mapper.start();
  scene.mapper.setTrackedFrame(11);
  scene.mapper.addKeyFrameMask(10, maskOverKeypoints(0, 6));
  for (int i = 0; i < 500 && !scene.mapper.isIdle(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_TRUE(scene.mapper.isIdle());
  scene.mapper.finish();
  std::lock_guard lock(scene.map.mutex);
  EXPECT_EQ(scene.culled(), 6);
}

// Keyframes 0-4 seeing the same row of points, but the points of keyframes 1 and 2 have all been
// culled; keyframe 4 is mapped.
struct OrphanedKeyFrames {
  map::Map map;
  LocalMapper mapper{map};
  std::vector<std::shared_ptr<map::KeyFrame>> keyframes;

  OrphanedKeyFrames() {
    for (std::uint64_t i = 0; i < 5; ++i) keyframes.push_back(map.createKeyFrame(rowFrame(i)));
    for (std::size_t k = 1; k < keyframes.size(); ++k) {
      for (std::size_t i = 0; i < testing::kKeypoints; ++i) {
        auto point = addPoint(map, *keyframes[k], i, {keyframes[0].get()});
        if (k == 1 || k == 2) point->setBad();
      }
    }
    for (const auto& keyframe : keyframes) keyframe->updateConnections();
    mapper.insertKeyFrame(keyframes[4]);
    mapper.processQueued();
  }
};

TEST(LocalMapper, AKeyFrameWhosePointsWereAllCulledIsCulled) {
  OrphanedKeyFrames scene;
  EXPECT_TRUE(scene.keyframes[1]->bad);
  EXPECT_FALSE(scene.keyframes[0]->bad);
  EXPECT_FALSE(scene.keyframes[4]->bad);
}

TEST(LocalMapper, ARecentKeyFrameWithoutPointsIsKeptUntilItsPointsAreJudged) {
  OrphanedKeyFrames scene;
  EXPECT_FALSE(scene.keyframes[2]->bad) << "its points are judged for three keyframes";
}

}  // namespace
}  // namespace segslam::mapping
