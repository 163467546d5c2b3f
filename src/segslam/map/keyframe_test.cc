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

TEST(KeyFrame, ItsParentIsAnOlderKeyFrameEvenWhenANewerOneIsCloser) {
  auto first = keyFrame(0);
  auto middle = keyFrame(1);
  auto last = keyFrame(2);
  const auto with_last = share(*middle, *last, 0);
  middle->updateConnections();
  EXPECT_EQ(middle->parent, nullptr) << "its only covisible keyframe is newer: it waits";
  last->updateConnections();
  EXPECT_EQ(last->parent, middle.get());
  const auto with_first = share(*first, *middle, kPoints);
  middle->updateConnections();
  EXPECT_EQ(middle->parent, first.get());
}

TEST(KeyFrame, RemovingAKeyFrameHandsItsChildrenToItsParentWithoutCycles) {
  auto first = keyFrame(0);
  auto middle = keyFrame(1);
  auto last = keyFrame(2);
  const auto with_last = share(*middle, *last, 0);
  middle->updateConnections();
  last->updateConnections();
  const auto with_first = share(*first, *middle, kPoints);
  middle->updateConnections();
  middle->setBad();
  EXPECT_EQ(last->parent, first.get());
  EXPECT_TRUE(first->children.contains(last.get()));
  EXPECT_NE(last->parent, last.get());
}

}  // namespace
}  // namespace segslam::map
