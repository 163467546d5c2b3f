#include "segslam/dense/keyframe_cloud.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace segslam::dense {
namespace {

core::Camera cloudCamera() {
  core::Camera camera;
  camera.width = 40;
  camera.height = 30;
  camera.fx = 50.0;
  camera.fy = 40.0;
  camera.cx = 19.5;
  camera.cy = 14.5;
  return camera;
}

// A fronto-parallel plane at depth z, grey, with a tiny voxel so every pixel is its own point.
KeyFrameImages plane(const core::Camera& camera, float z) {
  KeyFrameImages images;
  images.bgr = cv::Mat(camera.height, camera.width, CV_8UC3, cv::Scalar(10, 20, 30));
  images.depth = cv::Mat(camera.height, camera.width, CV_32FC1, cv::Scalar(z));
  return images;
}

KeyFrameCloudOptions pixelExactOptions() {
  KeyFrameCloudOptions options;
  options.voxel_size = 1e-4;
  options.mask_dilation_px = 0;
  return options;
}

TEST(KeyFrameCloud, PlaneAtKnownDepthGivesPinholePoints) {
  const auto camera = cloudCamera();
  const KeyFrameCloudMaker maker(camera, pixelExactOptions());
  const auto cloud = maker.make(plane(camera, 2.0f));
  ASSERT_EQ(cloud.static_points.size(), 40u * 30u);
  EXPECT_TRUE(cloud.dynamic_points.empty());
  // Every pixel appears once: find u = 0, v = 0 and u = 39, v = 29 among the points.
  int corners = 0;
  for (std::size_t i = 0; i < cloud.static_points.size(); ++i) {
    const Eigen::Vector3f& p = cloud.static_points.points[i];
    EXPECT_NEAR(p.z(), 2.0f, 1e-5f);
    const Eigen::Vector3f top_left((0 - 19.5f) * 2.0f / 50.0f, (0 - 14.5f) * 2.0f / 40.0f, 2.0f);
    const Eigen::Vector3f bottom_right((39 - 19.5f) * 2.0f / 50.0f, (29 - 14.5f) * 2.0f / 40.0f,
                                       2.0f);
    if ((p - top_left).norm() < 1e-5f || (p - bottom_right).norm() < 1e-5f) ++corners;
    EXPECT_EQ(cloud.static_points.colours[i], (Rgb{30, 20, 10}));  // BGR image, RGB points
  }
  EXPECT_EQ(corners, 2);
}

TEST(KeyFrameCloud, MaskedPixelsGoToTheDynamicLayerAndInvalidDepthIsSkipped) {
  const auto camera = cloudCamera();
  auto images = plane(camera, 1.0f);
  images.depth(cv::Rect(0, 0, 10, 30)).setTo(0.0f);  // no measurement
  images.depth(cv::Rect(10, 0, 5, 30)).setTo(9.0f);  // beyond max_depth
  images.dynamic_mask = cv::Mat::zeros(camera.height, camera.width, CV_8UC1);
  images.dynamic_mask(cv::Rect(30, 0, 10, 30)).setTo(255);
  images.labels = cv::Mat(camera.height, camera.width, CV_8UC1, cv::Scalar(2));
  images.labels(cv::Rect(30, 0, 10, 30)).setTo(8);
  auto options = pixelExactOptions();
  options.depth_edge_ratio = 100.0;  // the steps above are not edges here
  const KeyFrameCloudMaker maker(camera, options);
  const auto cloud = maker.make(images);
  EXPECT_EQ(cloud.static_points.size(), 15u * 30u);
  EXPECT_EQ(cloud.dynamic_points.size(), 10u * 30u);
  for (auto label : cloud.static_points.labels) EXPECT_EQ(label, 2);
  for (auto label : cloud.dynamic_points.labels) EXPECT_EQ(label, 8);
}

TEST(KeyFrameCloud, DilationKeepsTheObjectBorderOutOfBothLayers) {
  const auto camera = cloudCamera();
  auto images = plane(camera, 1.0f);
  images.dynamic_mask = cv::Mat::zeros(camera.height, camera.width, CV_8UC1);
  images.dynamic_mask(cv::Rect(30, 0, 10, 30)).setTo(255);
  auto options = pixelExactOptions();
  options.mask_dilation_px = 3;
  const auto cloud = KeyFrameCloudMaker(camera, options).make(images);
  EXPECT_EQ(cloud.static_points.size(), 27u * 30u);
  EXPECT_EQ(cloud.dynamic_points.size(), 10u * 30u);
}

TEST(KeyFrameCloud, DepthDiscontinuitiesAreSkipped) {
  const auto camera = cloudCamera();
  auto images = plane(camera, 1.0f);
  images.depth(cv::Rect(20, 0, 20, 30)).setTo(2.0f);
  const auto cloud = KeyFrameCloudMaker(camera, pixelExactOptions()).make(images);
  EXPECT_EQ(cloud.static_points.size(), 38u * 30u);  // columns 19 and 20 lie on the step
}

TEST(KeyFrameCloud, VoxelsBoundThePointCount) {
  const auto camera = cloudCamera();
  auto options = pixelExactOptions();
  options.voxel_size = 0.5;
  const auto cloud = KeyFrameCloudMaker(camera, options).make(plane(camera, 2.0f));
  // The plane spans 1.6 m x 1.5 m: at most 5 x 5 voxels of 0.5 m (4 x 4 when aligned).
  EXPECT_GE(cloud.static_points.size(), 9u);
  EXPECT_LE(cloud.static_points.size(), 25u);
}

TEST(KeyFrameCloud, CoarseVoxelsSamplePixelsWithAStride) {
  const auto camera = cloudCamera();
  auto options = pixelExactOptions();
  options.voxel_size = 0.1;
  options.full_sampling_depth = 1.0;  // stride floor(0.1 m * 40 px / 1 m) = 4
  const KeyFrameCloudMaker maker(camera, options);
  EXPECT_EQ(maker.samplingStride(), 4);
  const auto points = maker.backProject(plane(camera, 1.0f)).static_points;
  EXPECT_EQ(points.size(), 10u * 8u);  // columns 0, 4, ..., 36; rows 0, 4, ..., 28
  // Neighbouring samples are 4 px * 1 m / 50 px = 8 cm apart, within one voxel.
  EXPECT_NEAR(points.points[1].x() - points.points[0].x(), 0.08f, 1e-5f);
  EXPECT_EQ(KeyFrameCloudMaker(camera, pixelExactOptions()).samplingStride(), 1);
}

TEST(KeyFrameCloud, WrongImageTypesAreRejected) {
  const auto camera = cloudCamera();
  const KeyFrameCloudMaker maker(camera, pixelExactOptions());
  auto images = plane(camera, 1.0f);
  images.depth.convertTo(images.depth, CV_16U);
  EXPECT_THROW((void)maker.make(images), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::dense
