#include "segslam/map/frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>

namespace segslam::map {
namespace {

constexpr double kBaseline = 0.08;
constexpr double kCloseDepthBaselines = 40.0;

FrameCamera cameraOfWidth(int width) {
  core::Camera camera;
  camera.width = width;
  camera.height = width * 3 / 4;
  camera.fx = 525.0 * width / 640.0;
  camera.fy = camera.fx;
  camera.cx = (width - 1) / 2.0;
  camera.cy = (camera.height - 1) / 2.0;
  return FrameCamera(camera, kBaseline, kCloseDepthBaselines, feature::ScaleLevels(8, 1.2));
}

TEST(FrameCamera, BfIsFxTimesTheBaseline) {
  const FrameCamera camera = cameraOfWidth(640);
  EXPECT_DOUBLE_EQ(camera.stereo.bf, 525.0 * kBaseline);
  EXPECT_DOUBLE_EQ(camera.close_depth_m, kCloseDepthBaselines * kBaseline);
}

// The same sensor at half the resolution: depth is as reliable in metres, so the depth trusted for
// new points must not double with the pixel size (a fixed bf made it 6.4 m instead of 3.2 m).
TEST(FrameCamera, HalfResolutionTrustsDepthAsFarAndHalvesTheDisparity) {
  const FrameCamera full = cameraOfWidth(640);
  const FrameCamera half = cameraOfWidth(320);
  EXPECT_DOUBLE_EQ(half.close_depth_m, full.close_depth_m);
  EXPECT_DOUBLE_EQ(half.stereo.bf, full.stereo.bf / 2.0);
}

TEST(Frame, RightCoordinateIsTheDisparityOfTheBaselineAtTheKeypointDepth) {
  const auto camera = std::make_shared<const FrameCamera>(cameraOfWidth(320));
  cv::Mat depth(camera->camera.height, camera->camera.width, CV_32F, cv::Scalar(2.0f));
  const std::vector<cv::KeyPoint> keypoints = {cv::KeyPoint(100.0f, 50.0f, 31.0f)};
  const Frame frame(0, 0.0, keypoints, cv::Mat(1, 32, CV_8U, cv::Scalar(0)), depth, cv::Mat(),
                    camera);
  EXPECT_FLOAT_EQ(frame.depth[0], 2.0f);
  EXPECT_NEAR(frame.right_u[0], 100.0 - 262.5 * kBaseline / 2.0, 1e-4);
}

TEST(KeypointGrid, FindsWhatABruteForceSearchFinds) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> x(0.0f, 639.9f);
  std::uniform_real_distribution<float> y(0.0f, 479.9f);
  std::vector<cv::KeyPoint> keypoints;
  for (int i = 0; i < 2000; ++i) {
    keypoints.emplace_back(x(random), y(random), 7.0f, -1.0f, 0.0f, i % 4);
  }
  const KeypointGrid grid(keypoints, cv::Rect2d(0.0, 0.0, 640.0, 480.0));
  for (const auto& [u, v, radius] :
       {std::tuple{320.0, 240.0, 15.0}, std::tuple{2.0, 3.0, 40.0}, std::tuple{639.0, 479.0, 8.0},
        std::tuple{100.0, 400.0, 0.5}}) {
    const std::vector<std::size_t> found = grid.featuresInArea(keypoints, u, v, radius, 1, 2);
    std::vector<std::size_t> expected;
    for (std::size_t i = 0; i < keypoints.size(); ++i) {
      const cv::Point2f& p = keypoints[i].pt;
      const double du = p.x - u;
      const double dv = p.y - v;
      if (keypoints[i].octave >= 1 && keypoints[i].octave <= 2 &&
          du * du + dv * dv < radius * radius) {
        expected.push_back(i);
      }
    }
    std::vector<std::size_t> sorted = found;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, expected) << "around " << u << ", " << v;
  }
  EXPECT_TRUE(KeypointGrid().featuresInArea(keypoints, 320.0, 240.0, 50.0).empty());
}

}  // namespace
}  // namespace segslam::map
