#include "segslam/synth/scene_builder.h"

#include <gtest/gtest.h>

namespace segslam::synth {
namespace {

TEST(SynthSceneBuilder, CountsInstancesAndPaintsEveryFaceOnFinish) {
  SceneBuilder builder(3);
  EXPECT_EQ(builder.beginObject(core::SemanticClass::kBox, "box"), 1);
  builder.addBox({0, 0, 0}, {0.2, 0.3, 0.1}, Material::kCardboard);
  EXPECT_EQ(builder.beginObject(core::SemanticClass::kTable, "table", true), 2);
  builder.addRect(Rect{}, Material::kWood);
  builder.finish();
  const auto objects = builder.takeObjects();
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].rects.size(), 6u);
  EXPECT_TRUE(objects[1].info.movable);
  EXPECT_EQ(objects[1].rects[0].surface.instance, 2);
  EXPECT_EQ(objects[1].rects[0].surface.semantic_class, core::SemanticClass::kTable);
  // A 1 m square at 4.5 mm per texel.
  const Texture* texture = objects[1].rects[0].surface.texture;
  EXPECT_EQ(texture->level(0).cols, 224);
  EXPECT_EQ(builder.takeTextures().size(), 7u);
}

TEST(SynthSceneBuilder, PlacesTheCurrentObject) {
  SceneBuilder builder(3);
  builder.beginObject(core::SemanticClass::kChair, "chair");
  builder.addRect(Rect{}, Material::kWood);
  geometry::Pose placement = geometry::Pose::Identity();
  placement.translation() = Eigen::Vector3d(1, 2, 0);
  builder.placeCurrentObject(placement);
  EXPECT_TRUE(builder.takeObjects()[0].rects[0].shape.origin.isApprox(Eigen::Vector3d(1, 2, 0)));
}

TEST(SynthSceneBuilder, SameSeedSameTextures) {
  const auto paint = [](std::uint32_t seed) {
    SceneBuilder builder(seed);
    builder.beginObject(core::SemanticClass::kWall, "wall");
    builder.addRect(Rect{}, Material::kWallpaper);
    builder.finish();
    return builder.takeTextures()[0]->level(0).clone();
  };
  EXPECT_EQ(cv::norm(paint(4), paint(4), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(paint(4), paint(5), cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace segslam::synth
