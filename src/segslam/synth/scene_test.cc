#include "segslam/synth/scene.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "segslam/synth/room_layout.h"

namespace segslam::synth {
namespace {

SynthOptions sceneOptions(int people, bool moved_furniture, int frames = 90) {
  SynthOptions options;
  options.frames = frames;
  options.people = people;
  options.moved_furniture = moved_furniture;
  return options;
}

TEST(SynthScene, EveryObjectHasItsOwnInstanceAndTheRoomIsComplete) {
  const Scene scene(sceneOptions(3, false));
  std::map<core::SemanticClass, int> per_class;
  std::set<std::string> names;
  for (std::size_t i = 0; i < scene.objects().size(); ++i) {
    const SceneObject& object = scene.objects()[i];
    EXPECT_EQ(object.instance, i + 1);
    EXPECT_TRUE(names.insert(object.name).second) << object.name;
    ++per_class[object.semantic_class];
  }
  using C = core::SemanticClass;
  EXPECT_EQ(per_class[C::kWall], 4);
  EXPECT_EQ(per_class[C::kFloor], 1);
  EXPECT_EQ(per_class[C::kCeiling], 1);
  EXPECT_EQ(per_class[C::kPerson], 3);
  EXPECT_EQ(per_class[C::kChair], 2);
  for (C c : {C::kTable, C::kCabinet, C::kBox, C::kMonitor, C::kShelf}) EXPECT_GE(per_class[c], 1);
}

TEST(SynthScene, WalkingPeopleAreDynamicInEveryFrame) {
  const Scene scene(sceneOptions(2, false));
  for (int k = 0; k < scene.frameCount(); ++k) {
    const auto moving = scene.dynamicObjectsAt(k);
    ASSERT_EQ(moving.size(), 2u) << "frame " << k;
    for (const ObjectPosition& object : moving) {
      EXPECT_EQ(object.semantic_class, core::SemanticClass::kPerson);
      EXPECT_TRUE(roomBox().contains(object.position));
      EXPECT_DOUBLE_EQ(object.position.z(), 0.0);
    }
  }
  const RenderScene surfaces = scene.renderSceneAt(10);
  EXPECT_FALSE(surfaces.ellipsoids.empty());
  for (const auto& part : surfaces.ellipsoids) EXPECT_TRUE(part.surface.dynamic);
  for (const auto& rect : surfaces.rects) EXPECT_FALSE(rect.surface.dynamic);
}

TEST(SynthScene, PushedChairIsDynamicOnlyDuringItsPush) {
  const int frames = 100;
  const Scene scene(sceneOptions(0, true, frames));
  int dynamic_frames = 0;
  std::uint16_t chair = 0;
  for (int k = 0; k < frames; ++k) {
    const auto moving = scene.dynamicObjectsAt(k);
    if (moving.empty()) continue;
    ASSERT_EQ(moving.size(), 1u);
    EXPECT_EQ(moving[0].semantic_class, core::SemanticClass::kChair);
    chair = moving[0].instance;
    ++dynamic_frames;
    // The push runs during [0.3, 0.55] of the duration (99 frames), plus the frames touching it.
    EXPECT_GE(k, 29);
    EXPECT_LE(k, 55);
  }
  EXPECT_GE(dynamic_frames, 24);
  ASSERT_NE(chair, 0);
  EXPECT_FALSE(scene.isDynamic(chair, 0));
  EXPECT_FALSE(scene.isDynamic(chair, frames - 1));
}

TEST(SynthScene, NothingMovesWithoutPeopleAndFurniture) {
  const Scene scene(sceneOptions(0, false, 20));
  for (int k = 0; k < 20; ++k) EXPECT_TRUE(scene.dynamicObjectsAt(k).empty());
  for (const SceneObject& object : scene.objects()) EXPECT_FALSE(object.movable);
}

TEST(SynthScene, PeopleStandingStillAreNotDynamic) {
  SynthOptions options = sceneOptions(2, false, 20);
  options.person_speed = 0.0;
  const Scene scene(options);
  for (int k = 0; k < 20; ++k) EXPECT_TRUE(scene.dynamicObjectsAt(k).empty());
}

}  // namespace
}  // namespace segslam::synth
