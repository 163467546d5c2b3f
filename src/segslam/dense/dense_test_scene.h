#pragma once

// A tiny camera and flat views for the dense-map tests (header-only, never linked into the
// library).

#include <cstdint>
#include <opencv2/core.hpp>

#include "segslam/core/camera.h"
#include "segslam/dense/keyframe_cloud.h"

namespace segslam::dense::test_scene {

// 32 x 24 pixels: a keyframe cloud of it is a few hundred points.
inline core::Camera smallCamera() {
  core::Camera camera;
  camera.width = 32;
  camera.height = 24;
  camera.fx = camera.fy = 40.0;
  camera.cx = 15.5;
  camera.cy = 11.5;
  return camera;
}

// A wall facing the camera at `depth` metres, all one grey, with no mask.
inline KeyFrameImages flatView(const core::Camera& camera, float depth, std::uint8_t grey) {
  KeyFrameImages images;
  images.bgr = cv::Mat(camera.height, camera.width, CV_8UC3, cv::Scalar::all(grey));
  images.depth = cv::Mat(camera.height, camera.width, CV_32FC1, cv::Scalar(depth));
  return images;
}

}  // namespace segslam::dense::test_scene
