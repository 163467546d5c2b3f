#include "segslam/map/keyframe.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace segslam::map {
namespace {

constexpr int kPoints = 20;  // more than the covisibility threshold of 15 shared points

std::shared_ptr<KeyFrame> keyFrame(std::uint64_t id) {
  const core::Camera camera;
  std::vector<cv::KeyPoint> keypoints;
  for (int i = 0; i < 2 * kPoints; ++i) keypoints.emplace_back(10.0f + 10.0f * i, 100.0f, 7.0f);
  const Frame frame(id, 0.0, keypoints, cv::Mat(2 * kPoints, 32, CV_8U, cv::Scalar(0)), cv::Mat(),
                    cv::Mat(),
                    std::make_shared<FrameCamera>(camera, kDefaultVirtualBaselineM, 40.0,
                                                  feature::ScaleLevels(8, 1.2)));
  return std::make_shared<KeyFrame>(id, frame);
}

// Map points seen by both keyframes, at keypoints [first, first + kPoints) of each.
std::vector<std::shared_ptr<MapPoint>> share(KeyFrame& a, KeyFrame& b, std::size_t first) {
  std::vector<std::shared_ptr<MapPoint>> points;
  for (std::size_t i = first; i < first + kPoints; ++i) {
    auto point = std::make_shared<MapPoint>(i, Eigen::Vector3d(0.0, 0.0, 2.0), &a);
    for (KeyFrame* keyframe : {&a, &b}) {
      point->addObservation(keyframe, i);
      keyframe->addMapPoint(point, i);
    }
    points.push_back(point);
  }
  return points;
}

// Keyframes 0, 1 and 2, where 1 first shares points only with the newer 2, and later with 0.
struct ThreeKeyFrames {
  std::shared_ptr<KeyFrame> first = keyFrame(0);
  std::shared_ptr<KeyFrame> middle = keyFrame(1);
  std::shared_ptr<KeyFrame> last = keyFrame(2);
  std::vector<std::shared_ptr<MapPoint>> with_last = share(*middle, *last, 0);
  std::vector<std::shared_ptr<MapPoint>> with_first;

  void connectMiddleToFirst() {
    with_first = share(*first, *middle, kPoints);
    middle->updateConnections();
  }
};

TEST(KeyFrame, ItsParentIsAnOlderKeyFrameEvenWhenANewerOneIsCloser) {
  ThreeKeyFrames keyframes;
  keyframes.middle->updateConnections();
  EXPECT_EQ(keyframes.middle->parent, nullptr) << "its only covisible keyframe is newer: it waits";
  keyframes.last->updateConnections();
  EXPECT_EQ(keyframes.last->parent, keyframes.middle.get());
  keyframes.connectMiddleToFirst();
  EXPECT_EQ(keyframes.middle->parent, keyframes.first.get());
}

TEST(KeyFrame, RemovingAKeyFrameHandsItsChildrenToItsParentWithoutCycles) {
  ThreeKeyFrames keyframes;
  keyframes.middle->updateConnections();
  keyframes.last->updateConnections();
  keyframes.connectMiddleToFirst();
  keyframes.middle->setBad();
  EXPECT_EQ(keyframes.last->parent, keyframes.first.get());
  EXPECT_TRUE(keyframes.first->children.contains(keyframes.last.get()));
}

TEST(KeyFrame, AReleasedKeyFrameKeepsOnlyItsPlaceInThePoseTree) {
  ThreeKeyFrames keyframes;
  keyframes.middle->updateConnections();
  keyframes.last->updateConnections();
  keyframes.connectMiddleToFirst();
  keyframes.middle->T_cw.translation() = Eigen::Vector3d(0.5, 0.0, 0.0);
  keyframes.middle->setBad();
  keyframes.middle->releaseFeatures();
  EXPECT_TRUE(keyframes.middle->released());
  EXPECT_EQ(keyframes.middle->size(), 0u);
  EXPECT_TRUE(keyframes.middle->descriptors.empty());
  EXPECT_TRUE(keyframes.middle->mapPoints().empty());
  for (const auto& point : keyframes.with_first) {
    EXPECT_FALSE(point->isObservedBy(keyframes.middle.get()));
  }
  // Frames tracked against it are still placed through its parent.
  EXPECT_EQ(keyframes.middle->parent, keyframes.first.get());
  EXPECT_TRUE(keyframes.middle->T_c_parent.translation().isApprox(Eigen::Vector3d(0.5, 0.0, 0.0)));
}

// A point made in this session goes when fewer than two keyframes see it; a point restored from a
// map file stays while one does: losing a keyframe is no evidence that the point is gone.
TEST(MapPoint, ARestoredPointStaysWhileOneKeyFrameSeesIt) {
  const auto older = keyFrame(1);
  const auto newer = keyFrame(2);
  const auto points = share(*older, *newer, 0);
  points[1]->restored = true;
  newer->setBad();
  EXPECT_TRUE(points[0]->bad);
  EXPECT_FALSE(points[1]->bad);
  EXPECT_EQ(points[1]->numObservations(), 1);
  points[1]->eraseObservation(older.get());
  EXPECT_TRUE(points[1]->bad);
}

}  // namespace
}  // namespace segslam::map
