#include "segslam/mapping/keyframe_mask.h"

#include <gtest/gtest.h>

#include "segslam/mapping/mapping_test_scene.h"

namespace segslam::mapping {
namespace {

using testing::addPoint;
using testing::maskOverKeypoints;
using testing::rowFrame;

// Keyframes 0 and 1 saw points 10-19 before; keyframe 2 matched them again and made points 0-9.
struct KeyFrameWithOlderPoints {
  map::Map map;
  std::shared_ptr<map::KeyFrame> first = map.createKeyFrame(rowFrame(0));
  std::shared_ptr<map::KeyFrame> second = map.createKeyFrame(rowFrame(5));
  std::shared_ptr<map::KeyFrame> keyframe = map.createKeyFrame(rowFrame(10));
  std::vector<std::shared_ptr<map::MapPoint>> own;
  std::vector<std::shared_ptr<map::MapPoint>> older;

  KeyFrameWithOlderPoints() {
    for (std::size_t i = 0; i < 10; ++i) own.push_back(addPoint(map, *keyframe, i));
    for (std::size_t i = 10; i < 20; ++i) {
      older.push_back(addPoint(map, *first, i, {second.get(), keyframe.get()}));
    }
  }
};

TEST(KeyFrameOwnMask, CullsThePointsTheKeyFrameMadeOnTheObject) {
  KeyFrameWithOlderPoints scene;
  const auto outcome = applyOwnMask(*scene.keyframe, maskOverKeypoints(0, 4));
  EXPECT_EQ(outcome.points_culled, 4);
  EXPECT_EQ(outcome.observations_dropped, 0);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(scene.own[i]->bad, i < 4) << i;
  for (const auto& point : scene.older) EXPECT_FALSE(point->bad);
}

TEST(KeyFrameOwnMask, AnOlderPointLosesTheObservationAndIsCulledWhenASecondKeyFrameAgrees) {
  KeyFrameWithOlderPoints scene;
  const auto outcome = applyOwnMask(*scene.keyframe, maskOverKeypoints(10, 12));
  EXPECT_EQ(outcome.points_culled, 0);
  EXPECT_EQ(outcome.observations_dropped, 2);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_FALSE(scene.older[k]->bad);
    EXPECT_EQ(scene.older[k]->moving_votes, 1);
    EXPECT_FALSE(scene.older[k]->isObservedBy(scene.keyframe.get()));
    EXPECT_EQ(scene.keyframe->mapPoints()[10 + k], nullptr);
  }
  // The second keyframe's own mask shows the same points moving.
  const auto second = applyOwnMask(*scene.second, maskOverKeypoints(10, 12));
  EXPECT_EQ(second.points_culled, 2);
  EXPECT_TRUE(scene.older[0]->bad);
  EXPECT_TRUE(scene.older[1]->bad);
  EXPECT_FALSE(scene.older[2]->bad);
}

TEST(KeyFrameOwnMask, JoinsTheKeyFramesMask) {
  KeyFrameWithOlderPoints scene;
  scene.keyframe->dynamic_mask = feature::RunLengthMask(maskOverKeypoints(30, 32));
  const cv::Mat own = maskOverKeypoints(0, 2);
  applyOwnMask(*scene.keyframe, own);
  EXPECT_EQ(cv::countNonZero(scene.keyframe->dynamic_mask.toMat()),
            cv::countNonZero(own) + cv::countNonZero(maskOverKeypoints(30, 32)));
  EXPECT_EQ(applyOwnMask(*scene.keyframe, cv::Mat()).points_culled, 0) << "no mask, no change";
}

}  // namespace
}  // namespace segslam::mapping
