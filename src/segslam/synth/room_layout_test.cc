#include "segslam/synth/room_layout.h"

#include <gtest/gtest.h>

#include "segslam/synth/synth_options.h"

namespace segslam::synth {
namespace {

TEST(SynthRoomLayout, FurnitureStaysInsideTheRoom) {
  SceneBuilder builder(1);
  buildRoom(builder, false);
  Eigen::AlignedBox3d room = roomBox();
  room.min().array() -= 1e-9;
  room.max().array() += 1e-9;
  const auto objects = builder.takeObjects();
  EXPECT_GE(objects.size(), 15u);
  for (const BuiltObject& object : objects) {
    ASSERT_FALSE(object.rects.empty()) << object.info.name;
    for (const TexturedRect& rect : object.rects) {
      for (const auto& corner : rect.shape.corners()) {
        EXPECT_TRUE(room.contains(corner)) << object.info.name;
      }
    }
  }
}

TEST(SynthRoomLayout, LanesStayInsideTheRoomClearOfTheWalls) {
  const Eigen::AlignedBox2d floor(Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(4.7, 4.5));
  ASSERT_GE(walkLanes().size(), static_cast<std::size_t>(kSynthMaxPeople));
  for (const WalkLane& lane : walkLanes()) {
    EXPECT_TRUE(floor.contains(lane.a));
    EXPECT_TRUE(floor.contains(lane.b));
    EXPECT_GT((lane.b - lane.a).norm(), 2.0);
  }
}

TEST(SynthRoomLayout, ChairIsPushedHalfAMetreToOneMetre) {
  const PushMotion push = chairPush(10.0);
  const double distance = (push.end.translation() - push.start.translation()).norm();
  EXPECT_GE(distance, 0.5);
  EXPECT_LE(distance, 1.0);
  EXPECT_DOUBLE_EQ(push.begin_time, 3.0);
  EXPECT_DOUBLE_EQ(push.end_time, 5.5);
}

}  // namespace
}  // namespace segslam::synth
