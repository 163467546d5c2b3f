#include "segslam/loop/loop_verifier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace segslam::loop {
namespace {

constexpr int kPoints = 300;

struct Scene {
  std::shared_ptr<const map::FrameCamera> camera = std::make_shared<map::FrameCamera>(
      core::Camera{}, map::kDefaultVirtualBaselineM, 40.0, feature::ScaleLevels(8, 1.2));
  std::vector<LoopMapPoint> points;  // world frame = the candidate's map
  geometry::Pose T_query_w = geometry::Pose::Identity();
  LoopQuery query;
};

cv::Mat randomDescriptor(std::mt19937& rng) {
  cv::Mat descriptor(1, 32, CV_8U);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int b = 0; b < 32; ++b)
    descriptor.at<std::uint8_t>(0, b) = static_cast<std::uint8_t>(byte(rng));
  return descriptor;
}

cv::Mat withFlippedBits(const cv::Mat& descriptor, int bits, std::mt19937& rng) {
  cv::Mat flipped = descriptor.clone();
  std::uniform_int_distribution<int> bit(0, 255);
  for (int k = 0; k < bits; ++k) {
    const int b = bit(rng);
    flipped.at<std::uint8_t>(0, b / 8) ^= static_cast<std::uint8_t>(1 << (b % 8));
  }
  return flipped;
}

void addKeypoint(Scene& scene, double u, double v, double z, const cv::Mat& descriptor) {
  LoopQuery& q = scene.query;
  q.keypoints_un.emplace_back(static_cast<float>(u), static_cast<float>(v), 7.0f);
  q.depth.push_back(static_cast<float>(z));
  q.right_u.push_back(static_cast<float>(u - scene.camera->stereo.bf / z));
  q.descriptors.push_back(descriptor);
}

// Points in a room seen by the candidate; the query keyframe looks at them from 30 cm aside,
// turned by 10 degrees, and also sees 150 features the map does not have.
Scene makeScene(std::uint32_t seed) {
  std::mt19937 rng(seed);
  Scene scene;
  std::uniform_real_distribution<double> x(-2.0, 2.0);
  std::uniform_real_distribution<double> y(-1.5, 1.5);
  std::uniform_real_distribution<double> z(1.5, 4.0);
  std::normal_distribution<double> pixel_noise(0.0, 0.3);
  for (int p = 0; p < kPoints; ++p) {
    scene.points.push_back({std::make_shared<map::MapPoint>(p, Eigen::Vector3d::Zero(), nullptr),
                            {x(rng), y(rng), z(rng)},
                            randomDescriptor(rng)});
    scene.points.back().point->position = scene.points.back().position;
  }
  scene.T_query_w.linear() =
      Eigen::AngleAxisd(0.17, Eigen::Vector3d(0.2, 1.0, 0.1).normalized()).toRotationMatrix();
  scene.T_query_w.translation() = Eigen::Vector3d(0.3, -0.05, 0.1);
  scene.query.camera = scene.camera;
  const auto& s = scene.camera->stereo;
  for (const LoopMapPoint& point : scene.points) {
    const Eigen::Vector3d p = scene.T_query_w * point.position;
    const double u = s.fx * p.x() / p.z() + s.cx + pixel_noise(rng);
    const double v = s.fy * p.y() / p.z() + s.cy + pixel_noise(rng);
    if (p.z() < 0.5 || u < 0 || v < 0 || u >= 640 || v >= 480) continue;
    addKeypoint(scene, u, v, p.z() * (1.0 + 0.002 * pixel_noise(rng)),
                withFlippedBits(point.descriptor, 6, rng));
  }
  std::uniform_real_distribution<double> column(0.0, 639.0);
  std::uniform_real_distribution<double> row(0.0, 479.0);
  for (int k = 0; k < 150; ++k)
    addKeypoint(scene, column(rng), row(rng), z(rng), randomDescriptor(rng));
  scene.query.grid = map::KeypointGrid(scene.query.keypoints_un, scene.camera->undistorted_bounds);
  return scene;
}

std::vector<LoopMapPoint> firstPoints(const Scene& scene, std::size_t n) {
  return {scene.points.begin(), scene.points.begin() + static_cast<std::ptrdiff_t>(n)};
}

TEST(LoopVerifier, AcceptsATrueLoopAndRecoversTheQueryPose) {
  const Scene scene = makeScene(3);
  ASSERT_GT(scene.query.keypoints_un.size(), 300u);
  const auto result = verifyLoop(scene.query, firstPoints(scene, 120), scene.points);
  EXPECT_TRUE(result.accepted);
  EXPECT_GE(result.ransac_inliers, 40);
  EXPECT_GT(result.inliers, result.ransac_inliers);  // the projection search found more
  const geometry::Pose error = result.T_cw * scene.T_query_w.inverse();
  EXPECT_LT(error.translation().norm(), 0.01);
  EXPECT_LT(geometry::rotationAngleAccurate(error), 0.005);
  EXPECT_EQ(result.matched_points.size(), static_cast<std::size_t>(result.inliers));
}

TEST(LoopVerifier, RejectsMatchingDescriptorsWithoutConsistentGeometry) {
  // A look-alike place: the same descriptors, but at unrelated positions.
  Scene scene = makeScene(5);
  std::mt19937 rng(7);
  std::vector<Eigen::Vector3d> positions;
  for (const auto& point : scene.points) positions.push_back(point.position);
  std::shuffle(positions.begin(), positions.end(), rng);
  for (std::size_t p = 0; p < scene.points.size(); ++p) scene.points[p].position = positions[p];
  const auto result = verifyLoop(scene.query, firstPoints(scene, 120), scene.points);
  EXPECT_GT(result.matches, 40);
  EXPECT_FALSE(result.accepted);
  EXPECT_LT(result.ransac_inliers, 40);
}

TEST(LoopVerifier, RejectsAnUnrelatedPlace) {
  const Scene scene = makeScene(9);
  const Scene other = makeScene(10);
  const auto result = verifyLoop(scene.query, firstPoints(other, 120), other.points);
  EXPECT_FALSE(result.accepted);
}

}  // namespace
}  // namespace segslam::loop
