#include "segslam/segmentation/geometric_segmenter.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "segslam/util/error.h"

namespace segslam::segmentation {
namespace {

cv::Mat texture(cv::Size size, int seed) {
  cv::Mat noise(size, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 1.5);
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  return noise;
}

// A textured wall 3 m away and a textured box 1.5 m away at column `box_x`, static camera.
DepthFrame scene(int box_x, const cv::Mat& wall, const cv::Mat& box) {
  DepthFrame frame{wall.clone(), cv::Mat(wall.size(), CV_32FC1, cv::Scalar(3.0f))};
  const cv::Rect where(box_x, 180, box.cols, box.rows);
  box.copyTo(frame.gray(where));
  frame.depth(where).setTo(1.5f);
  return frame;
}

core::Camera pinhole() {
  core::Camera camera;
  camera.width = 640;
  camera.height = 480;
  camera.fx = camera.fy = 525.0;
  camera.cx = 319.5;
  camera.cy = 239.5;
  return camera;
}

GeometricOptions withModel(CameraMotionModel model) {
  GeometricOptions options;
  options.motion_model = model;
  return options;
}

class GeometricSegmenterModels : public ::testing::TestWithParam<CameraMotionModel> {};

INSTANTIATE_TEST_SUITE_P(RigidAndHomography, GeometricSegmenterModels,
                         ::testing::Values(CameraMotionModel::kRigid,
                                           CameraMotionModel::kHomography));

TEST_P(GeometricSegmenterModels, FindsAMovingBoxAndLeavesTheBackgroundClean) {
  const cv::Mat wall = texture({640, 480}, 1);
  const cv::Mat box = texture({120, 100}, 2);
  const DepthFrame previous = scene(200, wall, box);
  const DepthFrame current = scene(214, wall, box);
  const cv::Mat dynamic =
      GeometricSegmenter(pinhole(), withModel(GetParam())).segment(previous, current);
  ASSERT_EQ(dynamic.size(), wall.size());
  cv::Mat truth = cv::Mat::zeros(wall.size(), CV_8UC1);
  truth(cv::Rect(214, 180, 120, 100)).setTo(255);
  const double found =
      cv::countNonZero(dynamic & truth) / static_cast<double>(cv::countNonZero(truth));
  const double background = cv::countNonZero(dynamic & ~truth) / static_cast<double>(wall.total());
  EXPECT_GT(found, 0.9);
  EXPECT_LT(background, 0.01);
}

TEST_P(GeometricSegmenterModels, StaticSceneUnderCameraMotionGivesNothing) {
  // A single plane seen by a camera moving sideways: everything moves, all of it explained by
  // the camera.
  const cv::Mat wall = texture({700, 480}, 3);
  DepthFrame previous{wall(cv::Rect(0, 0, 640, 480)).clone(),
                      cv::Mat(480, 640, CV_32FC1, cv::Scalar(3.0f))};
  DepthFrame current{wall(cv::Rect(6, 0, 640, 480)).clone(),
                     cv::Mat(480, 640, CV_32FC1, cv::Scalar(3.0f))};
  const cv::Mat dynamic =
      GeometricSegmenter(pinhole(), withModel(GetParam())).segment(previous, current);
  EXPECT_EQ(cv::countNonZero(dynamic), 0);
}

TEST(GeometricSegmenter, KnownDynamicPixelsAreLeftOutOfTheCameraMotion) {
  const cv::Mat wall = texture({640, 480}, 5);
  const cv::Mat box = texture({300, 280}, 6);  // a large mover that could bias the pose
  const DepthFrame previous = scene(100, wall, box);
  const DepthFrame current = scene(116, wall, box);
  cv::Mat known = cv::Mat::zeros(wall.size(), CV_8UC1);
  known(cv::Rect(116, 180, 300, 280)).setTo(255);
  const cv::Mat dynamic = GeometricSegmenter(pinhole()).segment(previous, current, known);
  cv::Mat background = ~known;
  EXPECT_LT(cv::countNonZero(dynamic & background), 0.01 * wall.total());
}

// A mover that holds most of the corners (a near box, its texture stronger than the wall's): RANSAC
// then takes its motion for the camera's, and the box is lost. Told what moved in the previous
// frame, the segmenter estimates the camera motion from the rest and finds the box.
TEST(GeometricSegmenter, WhatMovedInThePreviousFrameIsLeftOutOfTheCameraMotion) {
  cv::Mat wall = texture({640, 480}, 10);
  wall.convertTo(wall, CV_8UC1, 0.6, 50.0);
  const cv::Mat box = texture({300, 240}, 11);
  DepthFrame previous = scene(100, wall, box);
  const DepthFrame current = scene(116, wall, box);
  cv::Mat truth = cv::Mat::zeros(wall.size(), CV_8UC1);
  truth(cv::Rect(116, 180, 300, 240)).setTo(255);
  auto found = [&](const cv::Mat& dynamic) {
    return dynamic.empty()
               ? 0.0
               : cv::countNonZero(dynamic & truth) / static_cast<double>(cv::countNonZero(truth));
  };
  const GeometricSegmenter segmenter(pinhole());
  EXPECT_LT(found(segmenter.segment(previous, current)), 0.5);

  previous.moving = cv::Mat::zeros(wall.size(), CV_8UC1);
  previous.moving(cv::Rect(100, 180, 300, 240)).setTo(255);
  const cv::Mat dynamic = segmenter.segment(previous, current);
  ASSERT_FALSE(dynamic.empty());
  EXPECT_GT(found(dynamic), 0.9);
  EXPECT_LT(cv::countNonZero(dynamic & ~truth), 0.01 * wall.total());
}

// A static table top (one depth-connected region) with a small patch of its texture sliding:
// the few corners on the patch are outvoted by the many the camera motion explains, so the
// table is not masked. Without the share rule the same seeds mask the whole table, which is
// what made walker and synthetic frames lose their real movers to the moving-area cap.
TEST_P(GeometricSegmenterModels, FewMovingCornersDoNotMaskALargeStaticSurface) {
  const cv::Mat wall = texture({640, 480}, 7);
  const cv::Mat table = texture({320, 200}, 8);
  const cv::Mat patch_texture = texture({120, 60}, 9);
  auto withPatchAt = [&](int patch_x) {
    cv::Mat top = table.clone();
    patch_texture(cv::Rect(patch_x, 0, 60, 60)).copyTo(top(cv::Rect(130, 70, 60, 60)));
    return scene(160, wall, top);
  };
  const DepthFrame previous = withPatchAt(0);
  const DepthFrame current = withPatchAt(8);
  const cv::Rect table_area(160, 180, 320, 200);

  const cv::Mat dynamic =
      GeometricSegmenter(pinhole(), withModel(GetParam())).segment(previous, current);
  EXPECT_LT(cv::countNonZero(dynamic(table_area)), 0.05 * table_area.area());

  GeometricOptions any_share = withModel(GetParam());
  any_share.min_seed_share = 0.0;
  const cv::Mat masked_table = GeometricSegmenter(pinhole(), any_share).segment(previous, current);
  ASSERT_FALSE(masked_table.empty());
  EXPECT_GT(cv::countNonZero(masked_table(table_area)), 0.9 * table_area.area());
}

TEST(CameraMotionModel, FromName) {
  EXPECT_EQ(cameraMotionModelFromName("rigid"), CameraMotionModel::kRigid);
  EXPECT_EQ(cameraMotionModelFromName("homography"), CameraMotionModel::kHomography);
  EXPECT_THROW(cameraMotionModelFromName("affine"), util::Error);
}

}  // namespace
}  // namespace segslam::segmentation
