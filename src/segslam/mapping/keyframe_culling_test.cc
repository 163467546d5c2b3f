#include "segslam/mapping/keyframe_culling.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "segslam/mapping/mapping_test_scene.h"

namespace segslam::mapping {
namespace {

using testing::addPoint;
using testing::rowFrame;

constexpr std::size_t kKeypoints = testing::kKeypoints;

// A keyframe whose first `shared` keypoints' points are also seen by three other keyframes at
// the same keypoints and scale; its other points are its own.
struct SharedPoints {
  map::Map map;
  std::shared_ptr<map::KeyFrame> keyframe = map.createKeyFrame(rowFrame(10));
  std::vector<std::shared_ptr<map::KeyFrame>> others = {map.createKeyFrame(rowFrame(1)),
                                                        map.createKeyFrame(rowFrame(2)),
                                                        map.createKeyFrame(rowFrame(3))};

  explicit SharedPoints(std::size_t shared) {
    for (std::size_t i = 0; i < kKeypoints; ++i) {
      if (i < shared) {
        addPoint(map, *keyframe, i, {others[0].get(), others[1].get(), others[2].get()});
      } else {
        addPoint(map, *keyframe, i);
      }
    }
    keyframe->updateConnections();
    for (const auto& other : others) other->updateConnections();
  }
};

TEST(KeyFrameCulling, AKeyFrameWhosePointsOthersSeeIsRedundant) {
  EXPECT_TRUE(isRedundant(*SharedPoints(kKeypoints).keyframe, {}));
}

TEST(KeyFrameCulling, AKeyFrameWithATenthOfItsPointsItsOwnIsNotRedundant) {
  EXPECT_FALSE(isRedundant(*SharedPoints(kKeypoints - kKeypoints / 10).keyframe, {}));
}

// A keyframe and a twin at a pose of its own choosing that sees `shared` of its points, and
// `twin_extra` points besides.
struct Twins {
  map::Map map;
  std::shared_ptr<map::KeyFrame> keyframe = map.createKeyFrame(rowFrame(10));
  std::shared_ptr<map::KeyFrame> twin = map.createKeyFrame(rowFrame(40));

  Twins(std::size_t shared, std::size_t twin_extra, const Eigen::Isometry3d& T_twin_keyframe) {
    twin->T_cw = T_twin_keyframe * keyframe->T_cw;
    for (std::size_t i = 0; i < kKeypoints; ++i) {
      if (i < shared) {
        addPoint(map, *keyframe, i, {twin.get()});
      } else {
        addPoint(map, *keyframe, i);
      }
    }
    for (std::size_t i = shared; i < shared + twin_extra && i < kKeypoints; ++i) {
      addPoint(map, *twin, i);
    }
    keyframe->updateConnections();
    twin->updateConnections();
  }
};

Eigen::Isometry3d shifted(double x) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().x() = x;
  return pose;
}

Eigen::Isometry3d turned(double degrees) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitY()).matrix();
  return pose;
}

TEST(KeyFrameCulling, AKeyFrameWithAStrongerTwinAtTheSamePlaceIsCrowded) {
  const Twins twins(30, 10, shifted(0.01));
  EXPECT_TRUE(isCrowded(*twins.keyframe, {}));
  EXPECT_FALSE(isRedundant(*twins.keyframe, {}));
}

TEST(KeyFrameCulling, OfTwoTwinsTheOneWithFewerPointsIsTheCrowdedOne) {
  const Twins twins(30, 0, shifted(0.01));
  EXPECT_TRUE(isCrowded(*twins.twin, {}));
  EXPECT_FALSE(isCrowded(*twins.keyframe, {}));
}

TEST(KeyFrameCulling, ATwinFartherThanTheCrowdedDistanceLeavesTheKeyFrame) {
  EXPECT_FALSE(isCrowded(*Twins(30, 10, shifted(0.05)).keyframe, {}));
}

TEST(KeyFrameCulling, ATwinLookingElsewhereLeavesTheKeyFrame) {
  EXPECT_FALSE(isCrowded(*Twins(30, 10, turned(20.0)).keyframe, {}));
  EXPECT_TRUE(isCrowded(*Twins(30, 10, turned(5.0)).keyframe, {}));
}

TEST(KeyFrameCulling, ATwinSeeingUnderHalfOfTheKeyFramesPointsLeavesIt) {
  EXPECT_FALSE(isCrowded(*Twins(15, 25, shifted(0.01)).keyframe, {}));
}

TEST(KeyFrameCulling, NoCrowdingWhenTheShareIsZero) {
  KeyFrameCullingOptions options;
  options.crowded_covisible_share = 0.0;
  EXPECT_FALSE(isCrowded(*Twins(30, 10, shifted(0.01)).keyframe, options));
}

TEST(KeyFrameCulling, ACulledTwinLeavesTheKeyFrame) {
  const Twins twins(30, 10, shifted(0.01));
  twins.twin->setBad();
  EXPECT_FALSE(isCrowded(*twins.keyframe, {}));
}

TEST(KeyFrameCulling, AKeyFrameWithFewPointsLeftIsOrphaned) {
  SharedPoints scene(0);
  EXPECT_FALSE(isOrphaned(*scene.keyframe, {}));
  for (const auto& [index, point] : scene.keyframe->validMapPoints()) {
    if (index >= 10) point->setBad();
  }
  EXPECT_TRUE(isOrphaned(*scene.keyframe, {})) << "10 points left";
  KeyFrameCullingOptions never;
  never.orphaned_below_points = 0;
  EXPECT_FALSE(isOrphaned(*scene.keyframe, never));
}

}  // namespace
}  // namespace segslam::mapping
