#include "segslam/tracking/free_space_check.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace segslam::tracking {
namespace {

constexpr double kWallDepth = 3.0;

// A camera at the origin looking at a wall 3 m away, with a hole in its depth at the centre.
map::Frame frameFacingWall() {
  const core::Camera camera;
  cv::Mat depth(camera.height, camera.width, CV_32F, cv::Scalar(kWallDepth));
  depth(cv::Rect(static_cast<int>(camera.cx) - 5, static_cast<int>(camera.cy) - 5, 11, 11)) = 0.0f;
  map::Frame frame(0, 0.0, {}, cv::Mat(0, 32, CV_8U), depth, cv::Mat(),
                   std::make_shared<map::FrameCamera>(camera, map::kDefaultVirtualBaselineM, 40.0,
                                                      feature::ScaleLevels(8, 1.2)));
  frame.T_cw = geometry::Pose::Identity();
  frame.has_pose = true;
  return frame;
}

std::shared_ptr<map::MapPoint> pointAt(double x, double y, double z) {
  return std::make_shared<map::MapPoint>(0, Eigen::Vector3d(x, y, z), nullptr);
}

bool contains(const std::vector<std::shared_ptr<map::MapPoint>>& points,
              const std::shared_ptr<map::MapPoint>& point) {
  return std::find(points.begin(), points.end(), point) != points.end();
}

TEST(FreeSpaceCheck, APointInFrontOfTheMeasuredWallIsSeenThrough) {
  const auto floating = pointAt(0.5, 0.2, 1.5);
  const auto seen = pointsSeenThrough({floating}, frameFacingWall());
  EXPECT_TRUE(contains(seen, floating));
}

TEST(FreeSpaceCheck, PointsOnOrBehindTheSurfaceAreNot) {
  const auto on_wall = pointAt(0.5, 0.2, kWallDepth);
  const auto within_noise = pointAt(-0.4, 0.1, kWallDepth - 0.25);
  const auto occluded = pointAt(0.3, -0.3, kWallDepth + 1.0);
  const auto seen = pointsSeenThrough({on_wall, within_noise, occluded}, frameFacingWall());
  EXPECT_TRUE(seen.empty());
}

TEST(FreeSpaceCheck, NoJudgementWithoutAFullDepthWindowOrOutsideTheView) {
  const auto over_hole = pointAt(0.0, 0.0, 1.0);
  const auto behind_camera = pointAt(0.0, 0.2, -1.0);
  const auto outside_image = pointAt(5.0, 0.0, 1.0);
  const auto seen = pointsSeenThrough({over_hole, behind_camera, outside_image}, frameFacingWall());
  EXPECT_TRUE(seen.empty());
}

TEST(FreeSpaceCheck, BadPointsAreSkipped) {
  const auto floating = pointAt(0.5, 0.2, 1.5);
  floating->bad = true;
  EXPECT_TRUE(pointsSeenThrough({floating}, frameFacingWall()).empty());
}

}  // namespace
}  // namespace segslam::tracking
