#include "segslam/dense/map_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "segslam/dense/dense_test_scene.h"
#include "segslam/segmentation/semantic_class_map.h"

namespace segslam::dense {
namespace {

using test_scene::flatView;

MapBuilderOptions testOptions() {
  MapBuilderOptions options;
  options.keyframe.voxel_size = 0.005;
  options.cleaning.outlier_neighbours = 0;
  return options;
}

geometry::Pose translation(double x, double y, double z) {
  geometry::Pose pose = geometry::Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

TEST(MapBuilder, TwoKeyFramesArePlacedByTheirPoses) {
  const auto camera = test_scene::smallCamera();
  MapBuilder builder(camera, testOptions());
  builder.addKeyFrame(0, 1.0, flatView(camera, 1.0f, 50));
  builder.addKeyFrame(1, 2.0, flatView(camera, 1.0f, 200));
  core::Trajectory poses;
  poses.append(1.0, translation(0.0, 0.0, 0.0));
  poses.append(2.0, translation(10.0, 0.0, 5.0));  // far apart: the views do not overlap
  const DenseMap map = builder.build(poses);
  EXPECT_EQ(builder.numKeyFrames(), 2u);
  ASSERT_GT(map.static_points.size(), 100u);
  std::size_t first = 0;
  std::size_t second = 0;
  for (std::size_t i = 0; i < map.static_points.size(); ++i) {
    const Eigen::Vector3f& p = map.static_points.points[i];
    if (map.static_points.colours[i][0] == 50) {
      ++first;
      EXPECT_NEAR(p.z(), 1.0f, 1e-4f);
      EXPECT_LT(std::abs(p.x()), 0.41f);
    } else {
      ++second;
      EXPECT_EQ(map.static_points.colours[i][0], 200);
      EXPECT_NEAR(p.z(), 6.0f, 1e-4f);
      EXPECT_NEAR(p.x(), 10.0f, 0.41f);
    }
  }
  EXPECT_EQ(first, second);
  EXPECT_TRUE(map.dynamic_points.empty());
  EXPECT_DOUBLE_EQ(map.voxel_size, 0.005);
}

TEST(MapBuilder, KeyFramesWithoutPoseAreLeftOutAndRebuildsFollowNewPoses) {
  const auto camera = test_scene::smallCamera();
  MapBuilder builder(camera, testOptions());
  builder.addKeyFrame(0, 1.0, flatView(camera, 1.0f, 50));
  builder.addKeyFrame(1, 2.0, flatView(camera, 1.0f, 200));
  core::Trajectory only_first;
  only_first.append(1.0, translation(0.0, 0.0, 0.0));
  const auto culled = builder.build(only_first);
  for (const auto& colour : culled.static_points.colours) EXPECT_EQ(colour[0], 50);

  core::Trajectory corrected;
  corrected.append(1.0, translation(0.0, 0.0, 3.0));
  const auto moved = builder.build(corrected);
  ASSERT_EQ(moved.static_points.size(), culled.static_points.size());
  for (const auto& p : moved.static_points.points) EXPECT_NEAR(p.z(), 4.0f, 1e-4f);
}

// Three keyframes: the second beside the first (it sees more of the wall), the third far away;
// then a live set without the second, which culls it.
void cullTheSecondOfThreeViews(MapBuilder& builder, const core::Camera& camera) {
  builder.addKeyFrame(0, 1.0, flatView(camera, 1.0f, 50));
  builder.addKeyFrame(1, 2.0, flatView(camera, 1.0f, 200));
  builder.addKeyFrame(2, 3.0, flatView(camera, 1.0f, 120));
  core::Trajectory all;
  all.append(1.0, translation(0.0, 0.0, 0.0));
  all.append(2.0, translation(0.5, 0.0, 0.0));
  all.append(3.0, translation(10.0, 0.0, 5.0));
  builder.setLiveKeyFrames(all);
  core::Trajectory second_culled;
  second_culled.append(1.0, translation(0.0, 0.0, 0.0));
  second_culled.append(3.0, translation(10.0, 0.0, 5.0));
  builder.setLiveKeyFrames(second_culled);
}

// The first keyframe 1 m forward of where it was, the third where it was.
core::Trajectory firstMovedForward() {
  core::Trajectory moved;
  moved.append(1.0, translation(0.0, 0.0, 1.0));
  moved.append(3.0, translation(10.0, 0.0, 5.0));
  return moved;
}

// The map's points of the wall that only the second keyframe saw.
std::vector<std::size_t> onlySecondSaw(const DenseMap& map) {
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < map.static_points.size(); ++i) {
    const float x = map.static_points.points[i].x();
    if (x > 0.45f && x < 1.0f) indices.push_back(i);
  }
  return indices;
}

TEST(MapBuilder, CulledKeyFramesAreFoldedIntoTheNearestLiveOneAndMoveWithIt) {
  const auto camera = test_scene::smallCamera();
  MapBuilder builder(camera, testOptions());
  cullTheSecondOfThreeViews(builder, camera);
  EXPECT_EQ(builder.numKeyFrames(), 2u);  // one cloud fewer, its view kept in the first's

  const DenseMap map = builder.build(firstMovedForward());  // as a loop correction would
  const auto indices = onlySecondSaw(map);
  EXPECT_GT(indices.size(), 100u);
  for (const std::size_t i : indices) {
    EXPECT_EQ(map.static_points.colours[i][0], 200);
    EXPECT_NEAR(map.static_points.points[i].z(), 2.0f, 1e-4f);
  }
}

// Deterministic runs: each live set is folded as it is handed over, under its own poses. A map
// thread may fold only the latest of several sets it finds waiting, under the latest poses (here:
// the culled keyframe's wall would land at z = 1, not 2).
TEST(MapBuilder, SynchronousBuilderFoldsEachLiveSetUnderItsOwnPoses) {
  const auto camera = test_scene::smallCamera();
  MapBuilderOptions options = testOptions();
  options.synchronous = true;
  MapBuilder builder(camera, options);
  cullTheSecondOfThreeViews(builder, camera);
  builder.setLiveKeyFrames(firstMovedForward());  // before any map thread could have run

  const DenseMap map = builder.build(firstMovedForward());
  const auto indices = onlySecondSaw(map);
  EXPECT_GT(indices.size(), 100u);
  for (const std::size_t i : indices) EXPECT_NEAR(map.static_points.points[i].z(), 2.0f, 1e-4f);
}

TEST(MapBuilder, AnEarlierSessionsMapKeepsWhatThisRunDidNotSeeThrough) {
  const auto camera = test_scene::smallCamera();
  MapBuilder builder(camera, testOptions());
  LabelledCloud earlier;
  earlier.add({0.0f, 0.0f, 0.5f}, {7, 7, 7});   // in front of the wall this run sees: moved away
  earlier.add({0.0f, 0.0f, 1.0f}, {8, 8, 8});   // on that wall
  earlier.add({30.0f, 0.0f, 1.0f}, {9, 9, 9});  // where this run never looked
  builder.setEarlierMap(earlier);
  builder.addKeyFrame(0, 1.0, flatView(camera, 1.0f, 50));
  core::Trajectory poses;
  poses.append(1.0, translation(0.0, 0.0, 0.0));
  const DenseMap map = builder.build(poses);
  EXPECT_EQ(map.earlier_points_removed, 1u);
  bool far_kept = false;
  for (std::size_t i = 0; i < map.static_points.size(); ++i) {
    EXPECT_NE(map.static_points.colours[i][0], 7);
    far_kept = far_kept || map.static_points.colours[i][0] == 9;
  }
  EXPECT_TRUE(far_kept);
}

// A 3 x 3 patch far behind a wall: its centre pixel is no depth edge (its neighbours agree), so
// only the statistical outlier removal can keep it out of the map.
TEST(MapBuilder, IsolatedPointsAreCleanedFromTheMap) {
  const auto camera = test_scene::smallCamera();
  MapBuilderOptions options = testOptions();
  options.cleaning.outlier_neighbours = 8;
  MapBuilder builder(camera, options);
  KeyFrameImages view = flatView(camera, 1.0f, 50);
  view.depth(cv::Rect(20, 10, 3, 3)).setTo(2.5f);
  builder.addKeyFrame(0, 1.0, view);
  core::Trajectory poses;
  poses.append(1.0, translation(0.0, 0.0, 0.0));
  const DenseMap map = builder.build(poses);
  ASSERT_GT(map.static_points.size(), 100u);
  for (const auto& p : map.static_points.points) EXPECT_NEAR(p.z(), 1.0f, 1e-4f);

  options.cleaning.outlier_neighbours = 0;
  MapBuilder uncleaned(camera, options);
  uncleaned.addKeyFrame(0, 1.0, view);
  const DenseMap uncleaned_map = uncleaned.build(poses);
  const auto& kept = uncleaned_map.static_points.points;
  EXPECT_TRUE(std::any_of(kept.begin(), kept.end(), [](const auto& p) { return p.z() > 2.0f; }));
}

TEST(MapBuilder, NetworkLabelsGiveObjectsAndPeopleGoToTheDynamicLayer) {
  core::Camera camera;
  camera.width = 64;
  camera.height = 48;
  camera.fx = camera.fy = 80.0;  // 1.25 cm per pixel at 1 m
  camera.cx = 31.5;
  camera.cy = 23.5;
  auto images = flatView(camera, 1.0f, 100);
  // Pascal VOC class indices, as the network gives them: a tv monitor and a person.
  constexpr std::uint8_t kVocTvMonitor = 20;
  constexpr std::uint8_t kVocPerson = 15;
  cv::Mat voc_labels(camera.height, camera.width, CV_8UC1, cv::Scalar(0));
  voc_labels(cv::Rect(4, 4, 20, 20)).setTo(kVocTvMonitor);
  voc_labels(cv::Rect(44, 8, 16, 32)).setTo(kVocPerson);
  const std::vector<std::string> voc_classes = {
      "background", "aeroplane", "bicycle",     "bird",  "boat",        "bottle", "bus",
      "car",        "cat",       "chair",       "cow",   "diningtable", "dog",    "horse",
      "motorbike",  "person",    "pottedplant", "sheep", "sofa",        "train",  "tvmonitor"};
  images.labels = segmentation::SemanticClassMap(voc_classes).apply(voc_labels);
  images.dynamic_mask = (voc_labels == kVocPerson);

  auto options = testOptions();
  options.objects.min_points = 50;
  MapBuilder builder(camera, options);
  core::Trajectory poses;
  for (int k = 0; k < 3; ++k) {  // an object must be seen by three keyframes
    builder.addKeyFrame(static_cast<std::uint64_t>(k), 1.0 + k, images);
    poses.append(1.0 + k, translation(0.0, 0.0, 0.0));
  }
  const DenseMap map = builder.build(poses);

  ASSERT_EQ(map.objects.size(), 2u);
  const auto labelled = [&](const std::string& label) {
    return std::find_if(map.objects.begin(), map.objects.end(),
                        [&](const MapObject& object) { return object.label == label; });
  };
  ASSERT_NE(labelled("monitor"), map.objects.end());
  ASSERT_NE(labelled("person"), map.objects.end());
  const MapObject& monitor = *labelled("monitor");
  EXPECT_EQ(monitor.id, "monitor_1");
  EXPECT_FALSE(monitor.dynamic);
  EXPECT_EQ(monitor.points.size(), 400u);
  const MapObject& person = *labelled("person");
  // From the dynamic layer; standing still in all three keyframes, so not a moving object
  // (ObjectMapBuilder's tests have people walk).
  EXPECT_FALSE(person.dynamic);
  EXPECT_EQ(person.points.size(), 16u * 32u);
  const auto person_label = static_cast<std::uint8_t>(core::SemanticClass::kPerson);
  EXPECT_EQ(
      std::count(map.static_points.labels.begin(), map.static_points.labels.end(), person_label),
      0);
}

TEST(MapBuilder, BadImagesSurfaceAsErrors) {
  const auto camera = test_scene::smallCamera();
  MapBuilder builder(camera, testOptions());
  auto images = flatView(camera, 1.0f, 50);
  images.bgr = cv::Mat(3, 3, CV_8UC3);
  builder.addKeyFrame(0, 1.0, images);
  EXPECT_THROW(builder.finish(), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::dense
