#include "segslam/dense/keyframe_depth_view.h"

#include <gtest/gtest.h>

#include "segslam/dense/object_test_clouds.h"

namespace segslam::dense {
namespace {

using core::SemanticClass;
using test_clouds::addBox;

// A wall 4 m ahead of a camera at the origin (640 x 480, f = 525 px) looking down +z.
LabelledCloud wall() {
  LabelledCloud cloud;
  for (int i = -60; i <= 60; ++i) {
    for (int j = -40; j <= 40; ++j) {
      cloud.add({0.05f * static_cast<float>(i), 0.05f * static_cast<float>(j), 4.0f}, {9, 9, 9});
    }
  }
  return cloud;
}

struct Scene {
  LabelledCloud static_points = wall();
  LabelledCloud dynamic_points;

  [[nodiscard]] KeyFrameDepthView view(const Eigen::Isometry3d& T_cw) const {
    return {core::Camera(), T_cw, static_points, dynamic_points,
            segmentByLabel(dynamic_points, 0.05, 50)};
  }
  [[nodiscard]] KeyFrameDepthView view() const { return view(Eigen::Isometry3d::Identity()); }
};

// Where a person standing at 2 m was: the centroid of their box's surface.
const Eigen::Vector3f kPlace(0.2f, -0.5f, 2.15f);

void addPersonAt(LabelledCloud& cloud, float x, float z) {
  addBox(cloud, {x, -1.3f, z}, {x + 0.4f, 0.3f, z + 0.3f}, SemanticClass::kPerson);
}

TEST(KeyFrameDepthView, ThePersonStillThereIsTheirSegment) {
  Scene scene;
  addPersonAt(scene.dynamic_points, 0.0f, 2.0f);
  const PlaceSight sight = scene.view().look(kPlace);
  EXPECT_EQ(sight.kind, PlaceSight::Kind::kSegment);
  EXPECT_EQ(sight.segment, 0u);
  EXPECT_FALSE(sight.in_front);
}

TEST(KeyFrameDepthView, TheWallBehindAnEmptyPlaceShowsItEmpty) {
  Scene scene;
  addPersonAt(scene.dynamic_points, 1.0f, 2.0f);  // walked 1 m to the side
  EXPECT_EQ(scene.view().look(kPlace).kind, PlaceSight::Kind::kEmpty);
}

TEST(KeyFrameDepthView, SomeoneInFrontHidesThePlace) {
  Scene scene;
  addPersonAt(scene.dynamic_points, 0.0f, 1.0f);
  const PlaceSight sight = scene.view().look(kPlace);
  EXPECT_EQ(sight.kind, PlaceSight::Kind::kSegment);
  EXPECT_TRUE(sight.in_front);
}

TEST(KeyFrameDepthView, WhatItCannotTellIsUnseen) {
  Scene scene;
  EXPECT_EQ(KeyFrameDepthView().look(kPlace).kind, PlaceSight::Kind::kUnseen);
  // Behind the camera, and out of the image.
  EXPECT_EQ(scene.view().look({0.0f, 0.0f, -2.0f}).kind, PlaceSight::Kind::kUnseen);
  EXPECT_EQ(scene.view().look({5.0f, 0.0f, 2.0f}).kind, PlaceSight::Kind::kUnseen);
  // A pillar in front of the place.
  Scene pillar;
  addBox(pillar.static_points, {0.0f, -2.0f, 1.0f}, {0.4f, 1.0f, 1.1f}, SemanticClass::kNone);
  EXPECT_EQ(pillar.view().look(kPlace).kind, PlaceSight::Kind::kUnseen);
}

TEST(KeyFrameDepthView, AStaticSurfaceAtThePlaceIsStatic) {
  // The person there but missed by the mask: the surface the camera sees of them is in the static
  // layer.
  Scene missed;
  addBox(missed.static_points, {0.0f, -1.3f, 2.1f}, {0.4f, 0.3f, 2.15f}, SemanticClass::kNone);
  EXPECT_EQ(missed.view().look(kPlace).kind, PlaceSight::Kind::kStatic);
  // A cabinet there.
  Scene cabinet;
  addBox(cabinet.static_points, {0.0f, -1.0f, 2.1f}, {0.4f, 0.0f, 2.5f}, SemanticClass::kNone);
  EXPECT_EQ(cabinet.view().look(kPlace).kind, PlaceSight::Kind::kStatic);
}

TEST(KeyFrameDepthView, PlacesAreLookedAtFromTheKeyFramesPose) {
  Scene scene;
  addPersonAt(scene.dynamic_points, 1.0f, 2.0f);
  EXPECT_EQ(scene.view().look(kPlace).kind, PlaceSight::Kind::kEmpty);
  Eigen::Isometry3d T_cw = Eigen::Isometry3d::Identity();
  T_cw.translation() = Eigen::Vector3d(0.0, 0.0, -3.0);  // the camera 3 m on: the place behind it
  EXPECT_EQ(scene.view(T_cw).look(kPlace).kind, PlaceSight::Kind::kUnseen);
}

TEST(KeyFrameDepthView, TheRoomSeenBetweenTwoPlacesShowsThemApart) {
  // Two people side by side at 2 m, 0.3 m apart: the wall is seen between them.
  const Eigen::Vector3f left(0.2f, -0.5f, 2.15f);
  const Eigen::Vector3f right(0.9f, -0.5f, 2.15f);
  Scene beside;
  addPersonAt(beside.dynamic_points, 0.0f, 2.0f);
  addPersonAt(beside.dynamic_points, 0.7f, 2.0f);
  EXPECT_TRUE(beside.view().showsBackgroundBetween(left, right));
  EXPECT_TRUE(beside.view().showsBackgroundBetween(right, left));
  // One person cut in two by a table in front of their waist.
  const Eigen::Vector3f chest(0.2f, -0.9f, 2.15f);
  const Eigen::Vector3f legs(0.2f, 0.1f, 2.15f);
  Scene cut;
  addBox(cut.dynamic_points, {0.0f, -1.3f, 2.0f}, {0.4f, -0.5f, 2.3f}, SemanticClass::kPerson);
  addBox(cut.dynamic_points, {0.0f, -0.1f, 2.0f}, {0.4f, 0.3f, 2.3f}, SemanticClass::kPerson);
  addBox(cut.static_points, {-1.0f, -0.5f, 1.5f}, {1.0f, -0.1f, 1.6f}, SemanticClass::kNone);
  EXPECT_FALSE(cut.view().showsBackgroundBetween(chest, legs));
  // The same person with their waist missed by the mask: the waist is in the static layer, at
  // their depth, not behind them.
  Scene missed;
  addPersonAt(missed.static_points, 0.0f, 2.0f);
  addBox(missed.dynamic_points, {0.0f, -1.3f, 2.0f}, {0.4f, -0.5f, 2.3f}, SemanticClass::kPerson);
  addBox(missed.dynamic_points, {0.0f, -0.1f, 2.0f}, {0.4f, 0.3f, 2.3f}, SemanticClass::kPerson);
  EXPECT_FALSE(missed.view().showsBackgroundBetween(chest, legs));
  // Nothing to tell outside the image or without a view.
  EXPECT_FALSE(beside.view().showsBackgroundBetween(left, {9.0f, -0.5f, 2.15f}));
  EXPECT_FALSE(KeyFrameDepthView().showsBackgroundBetween(left, right));
}

}  // namespace
}  // namespace segslam::dense
