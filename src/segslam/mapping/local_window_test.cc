#include "segslam/mapping/local_window.h"

#include <gtest/gtest.h>

#include "segslam/mapping/mapping_test_scene.h"

namespace segslam::mapping {
namespace {

using testing::addPoint;
using testing::rowFrame;

// Keyframes made in id order (keyframe 0, always fixed, stays out of every window); `latest`
// makes a point at every keypoint, seen as listed by the others.
struct WindowScene {
  map::Map map;
  std::shared_ptr<map::KeyFrame> first = map.createKeyFrame(rowFrame(0));

  std::shared_ptr<map::KeyFrame> keyFrame(std::uint64_t frame_id) {
    return map.createKeyFrame(rowFrame(frame_id));
  }

  // Keypoints [begin, end) of `latest`, seen by `others` too.
  void sharePoints(map::KeyFrame& latest, std::size_t begin, std::size_t end,
                   const std::vector<map::KeyFrame*>& others) {
    for (std::size_t i = begin; i < end; ++i) addPoint(map, latest, i, others);
  }

  void connect() {
    for (const auto& keyframe : map.keyFrames()) keyframe->updateConnections();
  }
};

bool isFixed(const LocalWindow& window, const map::KeyFrame& keyframe) {
  for (const auto& k : window.problem.keyframes) {
    if (k.id == keyframe.id) return k.fixed;
  }
  ADD_FAILURE() << "keyframe " << keyframe.id << " not in the window";
  return false;
}

TEST(LocalWindow, KeyFramesOutsideThatSeeFewPointsDoNotHoldIt) {
  WindowScene scene;
  auto outside = scene.keyFrame(10);
  auto older = scene.keyFrame(20);
  auto recent = scene.keyFrame(30);
  auto latest = scene.keyFrame(40);
  scene.sharePoints(*latest, 0, 35, {older.get(), recent.get()});
  scene.sharePoints(*latest, 35, 40, {outside.get()});
  scene.connect();

  const LocalWindow window = collectLocalWindow(*latest, 3);
  ASSERT_EQ(window.keyframes.size(), 4u);
  EXPECT_TRUE(isFixed(window, *outside)) << "outside the window";
  EXPECT_TRUE(isFixed(window, *older)) << "5 observations by fixed keyframes hold nothing";
  EXPECT_FALSE(isFixed(window, *recent));
  EXPECT_FALSE(isFixed(window, *latest));
}

TEST(LocalWindow, KeyFramesOutsideThatSeeEnoughPointsHoldIt) {
  WindowScene scene;
  std::vector<std::shared_ptr<map::KeyFrame>> outside = {scene.keyFrame(10), scene.keyFrame(11),
                                                         scene.keyFrame(12)};
  auto older = scene.keyFrame(20);
  auto latest = scene.keyFrame(40);
  scene.sharePoints(*latest, 0, 35,
                    {older.get(), outside[0].get(), outside[1].get(), outside[2].get()});
  scene.sharePoints(*latest, 35, 40, {older.get()});
  scene.connect();

  const LocalWindow window = collectLocalWindow(*latest, 2);
  ASSERT_EQ(window.keyframes.size(), 5u);
  for (const auto& keyframe : outside) EXPECT_TRUE(isFixed(window, *keyframe));
  static_assert(3 * 35 >= kMinAnchorObservations);
  EXPECT_FALSE(isFixed(window, *older)) << "105 observations by fixed keyframes hold it";
  EXPECT_FALSE(isFixed(window, *latest));
}

TEST(LocalWindow, AWindowNoKeyFrameOutsideSeesIntoIsHeldByItsOldestKeyFrame) {
  WindowScene scene;
  auto older = scene.keyFrame(20);
  auto recent = scene.keyFrame(30);
  auto latest = scene.keyFrame(40);
  scene.sharePoints(*latest, 0, 40, {older.get(), recent.get()});
  scene.connect();

  const LocalWindow window = collectLocalWindow(*latest, 20);
  ASSERT_EQ(window.keyframes.size(), 3u);
  EXPECT_TRUE(isFixed(window, *older));
  EXPECT_FALSE(isFixed(window, *recent));
  EXPECT_FALSE(isFixed(window, *latest));
  EXPECT_EQ(window.problem.observations.size(), 3u * 40u);
  EXPECT_EQ(window.observation_owners.size(), window.problem.observations.size());
}

}  // namespace
}  // namespace segslam::mapping
