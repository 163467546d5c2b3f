#include "segslam/tracking/late_mask_check.h"

#include <gtest/gtest.h>

namespace segslam::tracking {
namespace {

// A person 1.5 m away in front of a wall at 3 m, masked as dynamic in the left half of the image.
struct PersonScene {
  core::Camera camera;
  map::FrameCamera frame_camera{camera, map::kDefaultVirtualBaselineM, 40.0,
                                feature::ScaleLevels(8, 1.2)};
  cv::Mat depth{camera.height, camera.width, CV_32F, cv::Scalar(3.0f)};
  cv::Mat mask{camera.height, camera.width, CV_8U, cv::Scalar(0)};

  PersonScene() {
    const cv::Rect person(0, 0, camera.width / 2, camera.height);
    depth(person) = 1.5f;
    mask(person) = 255;
  }
};

std::shared_ptr<map::MapPoint> mapPointAt(double x, double y, double z) {
  return std::make_shared<map::MapPoint>(0, Eigen::Vector3d(x, y, z), nullptr);
}

TEST(LateMaskCheck, PointsOnTheMaskedSurfaceAreFound) {
  const PersonScene scene;
  const auto on_person = mapPointAt(-0.3, 0.1, 1.5);
  const auto found = pointsOnDynamicSurface({on_person}, geometry::Pose::Identity(),
                                            scene.frame_camera, scene.mask, scene.depth);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found.front(), on_person);
}

TEST(LateMaskCheck, BackgroundBehindTheMaskAndOutsideItIsKept) {
  PersonScene scene;
  scene.depth(cv::Rect(scene.camera.width / 2, 0, scene.camera.width / 2, scene.camera.height)) =
      1.5f;
  const auto behind_person = mapPointAt(-0.6, 0.1, 3.0);
  const auto outside_mask = mapPointAt(0.3, 0.1, 1.5);
  const auto found =
      pointsOnDynamicSurface({behind_person, outside_mask}, geometry::Pose::Identity(),
                             scene.frame_camera, scene.mask, scene.depth);
  EXPECT_TRUE(found.empty());
}

TEST(LateMaskCheck, TheFramesPoseIsUsed) {
  const PersonScene scene;
  // In the world the point sits 1 m to the right; the frame's camera stood 1 m to the right too.
  const auto on_person = mapPointAt(0.7, 0.1, 1.5);
  geometry::Pose T_cw = geometry::Pose::Identity();
  T_cw.translation() = Eigen::Vector3d(-1.0, 0.0, 0.0);
  EXPECT_EQ(
      pointsOnDynamicSurface({on_person}, T_cw, scene.frame_camera, scene.mask, scene.depth).size(),
      1u);
  EXPECT_TRUE(pointsOnDynamicSurface({on_person}, geometry::Pose::Identity(), scene.frame_camera,
                                     scene.mask, scene.depth)
                  .empty());
}

// 50 points over the view: every fifth on the person (left half), the others on the wall.
std::vector<std::shared_ptr<map::MapPoint>> pointsOverTheView(const PersonScene& scene) {
  std::vector<std::shared_ptr<map::MapPoint>> points;
  for (int i = 0; i < 50; ++i) {
    const bool on_person = i % 5 == 0;
    const double z = on_person ? 1.5 : 3.0;
    const double u =
        on_person ? 0.1 * scene.camera.width + (i % 10) : 0.55 * scene.camera.width + i;
    const double v = 0.2 * scene.camera.height + 2 * i;
    points.push_back(mapPointAt((u - scene.camera.cx) * z / scene.camera.fx,
                                (v - scene.camera.cy) * z / scene.camera.fy, z));
  }
  return points;
}

TEST(LateMaskCheck, AMaskOverMostOfTheSurfaceIsASegmentationFailureAndCullsNothing) {
  PersonScene scene;
  const auto points = pointsOverTheView(scene);
  EXPECT_EQ(pointsOnDynamicSurface(points, geometry::Pose::Identity(), scene.frame_camera,
                                   scene.mask, scene.depth)
                .size(),
            10u);
  scene.mask.setTo(255);  // the whole frame "moves": wall points would go as well
  EXPECT_TRUE(pointsOnDynamicSurface(points, geometry::Pose::Identity(), scene.frame_camera,
                                     scene.mask, scene.depth)
                  .empty());
}

}  // namespace
}  // namespace segslam::tracking
