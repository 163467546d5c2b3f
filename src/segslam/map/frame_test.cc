#include "segslam/map/frame.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace segslam::map
