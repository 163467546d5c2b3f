#pragma once

// Small hand-made maps for the mapping tests (header-only, never linked into the library).

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "segslam/map/map.h"

namespace segslam::mapping::testing {

inline constexpr int kImageWidth = 640;
inline constexpr int kImageHeight = 480;
inline constexpr int kKeypoints = 40;

// Keypoints on a row across the image, every 15 pixels from x = 20, all 2 m away.
inline std::shared_ptr<const map::FrameCamera> frameCamera() {
  core::Camera camera;
  camera.width = kImageWidth;
  camera.height = kImageHeight;
  return std::make_shared<map::FrameCamera>(camera, map::kDefaultVirtualBaselineM, 40.0,
                                            feature::ScaleLevels(8, 1.2));
}

inline float keypointX(std::size_t i) { return 20.0f + 15.0f * static_cast<float>(i); }

inline map::Frame rowFrame(std::uint64_t frame_id) {
  std::vector<cv::KeyPoint> keypoints;
  for (std::size_t i = 0; i < kKeypoints; ++i) keypoints.emplace_back(keypointX(i), 240.0f, 7.0f);
  cv::Mat descriptors(kKeypoints, 32, CV_8U);
  cv::randu(descriptors, 0, 256);
  const cv::Mat depth(kImageHeight, kImageWidth, CV_32FC1, cv::Scalar(2.0f));
  map::Frame frame(frame_id, 0.1 * static_cast<double>(frame_id), keypoints, descriptors, depth,
                   cv::Mat(), frameCamera());
  frame.has_pose = true;
  return frame;
}

// A map point made by `maker` at its keypoint `index`, also seen by `others` at the same index.
inline std::shared_ptr<map::MapPoint> addPoint(map::Map& map, map::KeyFrame& maker,
                                               std::size_t index,
                                               const std::vector<map::KeyFrame*>& others = {}) {
  auto point = map.createMapPoint(maker.unproject(index), &maker);
  for (map::KeyFrame* keyframe : others) {
    point->addObservation(keyframe, index);
    keyframe->addMapPoint(point, index);
  }
  point->addObservation(&maker, index);
  maker.addMapPoint(point, index);
  point->updateDescriptor();
  point->updateNormalAndDepth();
  return point;
}

// A mask (CV_8UC1) marking the keypoints [first, last) of a row frame and nothing else.
inline cv::Mat maskOverKeypoints(std::size_t first, std::size_t last) {
  cv::Mat mask = cv::Mat::zeros(kImageHeight, kImageWidth, CV_8UC1);
  const int left = static_cast<int>(keypointX(first)) - 5;
  const int right = static_cast<int>(keypointX(last - 1)) + 5;
  mask(cv::Rect(left, 200, right - left, 80)) = 255;
  return mask;
}

}  // namespace segslam::mapping::testing
