#include "segslam/map/frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// A camera turning and sliding while its rows are read one after another (top to bottom for a
// positive readout): each keypoint is where the camera at its row's moment saw a static point.
// Compensated, every keypoint (and its depth) is where the camera at the middle row's moment sees
// that point.
void expectKeypointsAtTheMiddleRowsMoment(double readout_s) {
  FrameCamera frame_camera = cameraOfWidth(640);
  frame_camera.camera.rolling_shutter_readout_s = readout_s;
  const auto camera = std::make_shared<const FrameCamera>(frame_camera);
  const core::Camera& cam = camera->camera;
  // Per frame period of 1/30 s: 1.5 deg about y and 0.5 deg about x, 2 cm sideways.
  const double frame_dt = 1.0 / 30.0;
  geometry::Pose motion = geometry::Pose::Identity();
  motion.linear() = (Eigen::AngleAxisd(0.026, Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(0.009, Eigen::Vector3d::UnitX()))
                        .toRotationMatrix();
  motion.translation() = Eigen::Vector3d(0.02, 0.0, 0.005);
  const Eigen::AngleAxisd rotation(motion.linear());
  auto cameraAt = [&](double dt) {  // middle-row camera coordinates -> those dt seconds later
    geometry::Pose moved = geometry::Pose::Identity();
    moved.linear() =
        Eigen::AngleAxisd(rotation.angle() * dt / frame_dt, rotation.axis()).toRotationMatrix();
    moved.translation() = motion.translation() * dt / frame_dt;
    return moved;
  };
  std::vector<Eigen::Vector3d> points;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat depth(cam.height, cam.width, CV_32F, cv::Scalar(0.0f));
  for (int i = 0; i < 40; ++i) {
    // Every other keypoint has no depth: only the rotation moves it, as for a far point.
    const bool has_depth = i % 2 == 0;
    const Eigen::Vector3d point =
        cam.backProject(40.0 + 14.0 * i, 20.0 + 11.0 * i, has_depth ? 1.0 + 0.05 * i : 40.0);
    // Where the camera saw the point: iterate on the row, whose moment depends on where it is.
    Eigen::Vector2d uv = cam.project(point);
    Eigen::Vector3d seen = point;
    for (int k = 0; k < 5; ++k) {
      seen = cameraAt((uv.y() - 240.0) / 480.0 * readout_s) * point;
      uv = cam.project(seen);
    }
    points.push_back(point);
    keypoints.emplace_back(static_cast<float>(uv.x()), static_cast<float>(uv.y()), 31.0f);
    if (has_depth) {
      depth.at<float>(static_cast<int>(std::lround(uv.y())),
                      static_cast<int>(std::lround(uv.x()))) = static_cast<float>(seen.z());
    }
  }
  Frame frame(0, 0.0, keypoints, cv::Mat(40, 32, CV_8U, cv::Scalar(0)), depth, cv::Mat(), camera);
  const Frame as_read = frame;
  // A first, wrong motion, then the right one: each call starts from the keypoints as read.
  frame.compensateRollingShutter(motion.inverse(), frame_dt, readout_s);
  frame.compensateRollingShutter(motion, frame_dt, readout_s);
  double largest_before = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d truth = cam.project(points[i]);
    const cv::Point2f& pt = frame.keypoints_un[i].pt;
    const bool has_depth = i % 2 == 0;
    // First order in the rotation is left (and, without depth, the far point's slide).
    EXPECT_NEAR(pt.x, truth.x(), has_depth ? 0.05 : 0.2) << i;
    EXPECT_NEAR(pt.y, truth.y(), has_depth ? 0.05 : 0.2) << i;
    if (has_depth) {
      EXPECT_NEAR(frame.depth[i], points[i].z(), 1e-3) << i;
      EXPECT_NEAR(frame.right_u[i], pt.x - camera->stereo.bf / frame.depth[i], 1e-3) << i;
    }
    largest_before = std::max(largest_before, std::hypot(as_read.keypoints_un[i].pt.x - truth.x(),
                                                         as_read.keypoints_un[i].pt.y - truth.y()));
  }
  EXPECT_GT(largest_before, 3.0) << "the test's motion must move rows by pixels";
  EXPECT_FALSE(frame.grid
                   .featuresInArea(frame.keypoints_un, cam.project(points[7]).x(),
                                   cam.project(points[7]).y(), 0.5)
                   .empty());
}

TEST(Frame, RollingShutterCompensationMovesKeypointsToTheMiddleRowsMoment) {
  expectKeypointsAtTheMiddleRowsMoment(0.03);
}

// Frames played backwards, or a sensor mounted upside down whose images are turned upright.
TEST(Frame, RollingShutterCompensationOfRowsReadBottomUp) {
  expectKeypointsAtTheMiddleRowsMoment(-0.03);
}

TEST(Frame, GlobalShutterKeypointsStayWhereTheyWereRead) {
  const auto camera = std::make_shared<const FrameCamera>(cameraOfWidth(640));
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(2.0f));
  Frame frame(0, 0.0, {cv::KeyPoint(100.0f, 50.0f, 31.0f)}, cv::Mat(1, 32, CV_8U, cv::Scalar(0)),
              depth, cv::Mat(), camera);
  geometry::Pose motion = geometry::Pose::Identity();
  motion.translation() = Eigen::Vector3d(0.1, 0.0, 0.0);
  frame.compensateRollingShutter(motion, 1.0 / 30.0, 0.0);
  EXPECT_EQ(frame.keypoints_un[0].pt, cv::Point2f(100.0f, 50.0f));
  EXPECT_FLOAT_EQ(frame.depth[0], 2.0f);
}

// What estimating the readout relies on: the gradient is the derivative of the compensated
// keypoints with respect to the readout.
TEST(Frame, ReadoutGradientIsTheDerivativeOfTheCompensatedKeypoints) {
  const auto camera = std::make_shared<const FrameCamera>(cameraOfWidth(640));
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(1.5f));
  depth(cv::Rect(0, 0, 320, 480)) = 0.0f;  // keypoints without depth on the left
  std::vector<cv::KeyPoint> keypoints;
  for (int i = 0; i < 12; ++i) keypoints.emplace_back(30.0f + 50.0f * i, 20.0f + 40.0f * i, 31.0f);
  const Frame as_read(0, 0.0, keypoints, cv::Mat(12, 32, CV_8U, cv::Scalar(0)), depth, cv::Mat(),
                      camera);
  geometry::Pose motion = geometry::Pose::Identity();
  motion.linear() =
      Eigen::AngleAxisd(0.03, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()).toRotationMatrix();
  motion.translation() = Eigen::Vector3d(0.02, -0.01, 0.01);
  const double readout = 0.02;
  const double step = 1e-3;
  Frame at = as_read;
  Frame after = as_read;
  at.compensateRollingShutter(motion, 1.0 / 30.0, readout);
  after.compensateRollingShutter(motion, 1.0 / 30.0, readout + step);
  ASSERT_EQ(at.readout_gradient.size(), keypoints.size());
  for (std::size_t i = 0; i < keypoints.size(); ++i) {
    const double du = (after.keypoints_un[i].pt.x - at.keypoints_un[i].pt.x) / step;
    const double dv = (after.keypoints_un[i].pt.y - at.keypoints_un[i].pt.y) / step;
    EXPECT_NEAR(at.readout_gradient[i].x(), du, 2.0) << i;
    EXPECT_NEAR(at.readout_gradient[i].y(), dv, 2.0) << i;
  }
  EXPECT_GT(at.readout_gradient.back().norm(), 50.0) << "the bottom rows move with the readout";
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
