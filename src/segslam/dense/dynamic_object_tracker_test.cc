#include "segslam/dense/dynamic_object_tracker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "segslam/dense/object_test_clouds.h"

namespace segslam::dense {
namespace {

using core::SemanticClass;
using test_clouds::addBox;

// A person-sized box standing at (x, z) on the floor plane y = 0.
void addPerson(LabelledCloud& cloud, float x, float z, std::uint16_t instance = 0) {
  addBox(cloud, {x, -1.7f, z}, {x + 0.4f, 0.0f, z + 0.3f}, SemanticClass::kPerson, instance);
}

// The keyframes' camera: at the origin looking down +z, wide (f = 100 px) so that every person
// of these tests is in view, with a wall 8 m ahead behind them all.
core::Camera wideCamera() {
  core::Camera camera;
  camera.fx = camera.fy = 100.0;
  return camera;
}

const LabelledCloud& backdrop() {
  static const LabelledCloud wall = [] {
    LabelledCloud cloud;
    for (int i = -200; i <= 200; ++i) {
      for (int j = -80; j <= 40; ++j) {
        cloud.add({0.1f * static_cast<float>(i), 0.1f * static_cast<float>(j), 8.0f}, {9, 9, 9});
      }
    }
    return cloud;
  }();
  return wall;
}

// `cloud` the keyframe's dynamic layer; `static_points` its static layer.
void track(DynamicObjectTracker& tracker, std::uint64_t keyframe, double time,
           const LabelledCloud& cloud, const LabelledCloud& static_points) {
  const auto segments = segmentByLabel(cloud, tracker.options().cell_size, 50);
  tracker.addKeyFrame(keyframe, time, cloud, segments,
                      KeyFrameDepthView(wideCamera(), Eigen::Isometry3d::Identity(), static_points,
                                        cloud, segments));
}

void track(DynamicObjectTracker& tracker, std::uint64_t keyframe, double time,
           const LabelledCloud& cloud) {
  track(tracker, keyframe, time, cloud, backdrop());
}

TEST(DynamicObjectTracker, OneWalkingPersonIsOneTrack) {
  DynamicObjectTracker tracker({});
  // 1.2 m/s, keyframes half a second apart, the view cutting the person off now and then.
  for (int k = 0; k < 10; ++k) {
    LabelledCloud cloud;
    addPerson(cloud, 0.6f * static_cast<float>(k), 2.0f);
    track(tracker, static_cast<std::uint64_t>(k), 0.5 * k, cloud);
  }
  ASSERT_EQ(tracker.tracks().size(), 1u);
  EXPECT_EQ(tracker.tracks()[0].keyframes.size(), 10u);
  EXPECT_EQ(tracker.tracks()[0].instance, 0);
  // Each place of theirs after the first showed the wall in the keyframe before.
  EXPECT_TRUE(tracker.tracks()[0].arrived);
}

TEST(DynamicObjectTracker, TwoPeopleApartAreTwoTracksEvenWhenSplitBySomething) {
  DynamicObjectTracker tracker({});
  for (int k = 0; k < 6; ++k) {
    const float step = 0.3f * static_cast<float>(k);
    LabelledCloud cloud;
    addPerson(cloud, step, 2.0f);
    // The second person, 3 m further back, seen in two parts (a table hides their waist).
    addBox(cloud, {3.0f - step, -1.7f, 5.0f}, {3.4f - step, -0.9f, 5.3f}, SemanticClass::kPerson);
    addBox(cloud, {3.0f - step, -0.5f, 5.0f}, {3.4f - step, 0.0f, 5.3f}, SemanticClass::kPerson);
    track(tracker, static_cast<std::uint64_t>(k), 0.5 * k, cloud);
  }
  ASSERT_EQ(tracker.tracks().size(), 2u);
  EXPECT_EQ(tracker.tracks()[0].keyframes.size(), 6u);
  EXPECT_EQ(tracker.tracks()[1].keyframes.size(), 6u);
}

// Two people walking side by side, their bounds 0.45 m apart (within slack): the room seen
// between them keeps them two tracks, where joining by touching made them one.
TEST(DynamicObjectTracker, TwoPeopleSideBySideAreTwoTracks) {
  DynamicObjectTracker tracker({});
  for (int k = 0; k < 6; ++k) {
    const float step = 0.4f * static_cast<float>(k);
    LabelledCloud cloud;
    addPerson(cloud, step, 2.0f);
    addPerson(cloud, 0.85f + step, 2.0f);
    track(tracker, static_cast<std::uint64_t>(k), 0.5 * k, cloud);
  }
  ASSERT_EQ(tracker.tracks().size(), 2u);
  EXPECT_EQ(tracker.tracks()[0].keyframes.size(), 6u);
  EXPECT_EQ(tracker.tracks()[1].keyframes.size(), 6u);
}

TEST(DynamicObjectTracker, InstanceIdsAreFollowedAndOnlyAVeryLongAbsenceStartsANewTrack) {
  DynamicObjectTracker tracker({});
  LabelledCloud first;
  addPerson(first, 0.0f, 2.0f, 7);
  addPerson(first, 5.0f, 2.0f);
  track(tracker, 0, 0.0, first);
  LabelledCloud second;
  addPerson(second, 2.0f, 2.0f, 7);  // far from where it was: the id still says who it is
  addPerson(second, 5.0f, 2.0f);
  track(tracker, 1, 0.2, second);
  LabelledCloud later;
  addPerson(later, 5.0f, 2.0f);
  track(tracker, 2, 0.2 + 10.0, later);          // back after 10 s: the same person
  track(tracker, 3, 0.2 + 10.0 + 100.0, later);  // after 100 s: past max_gap, a new track
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 3u);
  const auto seven = std::find_if(tracks.begin(), tracks.end(),
                                  [](const DynamicTrack& t) { return t.instance == 7; });
  ASSERT_NE(seven, tracks.end());
  EXPECT_EQ(seven->keyframes.size(), 2u);
  const auto untracked = std::find_if(tracks.begin(), tracks.end(), [](const DynamicTrack& t) {
    return t.instance == 0 && t.keyframes.front() == 0;
  });
  ASSERT_NE(untracked, tracks.end());
  EXPECT_EQ(untracked->keyframes, (std::vector<std::uint64_t>{0, 1, 2}));
  EXPECT_EQ(tracks.back().keyframes, (std::vector<std::uint64_t>{3}));
}

// The held-out composite's case: a person seated still in the background the whole time, and one
// walking through the view, out of it for seconds, and back somewhere else.
TEST(DynamicObjectTracker, AWalkerWhoLeavesAndComesBackIsOneTrackBesideASeatedPerson) {
  DynamicObjectTracker tracker({});
  double time = 0.0;
  std::uint64_t keyframe = 0;
  const auto view = [&](std::optional<float> walker_x) {
    LabelledCloud cloud;
    addPerson(cloud, -1.0f, 4.0f);  // seated, still
    if (walker_x) addPerson(cloud, *walker_x, 1.5f);
    track(tracker, keyframe++, time, cloud);
  };
  for (int k = 0; k < 4; ++k, time += 0.5) view(0.5f * static_cast<float>(k));
  time += 6.0;  // out of view for 6 s
  view(std::nullopt);
  time += 0.5;
  for (int k = 0; k < 3; ++k, time += 0.5) view(3.0f - 0.5f * static_cast<float>(k));
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].keyframes.size(), 8u);  // the seated person, seen in every keyframe
  EXPECT_LT(tracks[0].travelled, 0.1f);
  EXPECT_EQ(tracks[1].keyframes.size(), 7u);
  EXPECT_NEAR(tracks[1].travelled, 3.0f, 0.05f);
}

// A seated person and a walker passing 1 m in front of them, both out of view for 3 s; then a part
// of the seated person where they sat (under min_reach_points: a still track's reach is slack). It
// is nearer the seated person's place than the walker's by far: it continues the seated person,
// though the walker's reach after 3 s is 13 times as long (by distance relative to each track's
// own reach, the walker took it, and came back later as a second track).
TEST(DynamicObjectTracker, APartOfASeatedPersonStaysTheirsAfterAnAbsence) {
  DynamicObjectTracker tracker({});
  for (int k = 0; k < 2; ++k) {
    LabelledCloud cloud;
    addPerson(cloud, -1.0f, 4.0f);
    addPerson(cloud, k == 0 ? 0.4f : -0.6f, 3.0f);  // walking to the left
    track(tracker, static_cast<std::uint64_t>(k), 0.5 * k, cloud);
  }
  LabelledCloud part;
  addBox(part, {-0.9f, -1.2f, 3.95f}, {-0.8f, -1.0f, 4.0f}, SemanticClass::kPerson);
  ASSERT_GT(part.size(), tracker.options().min_track_points);
  ASSERT_LT(part.size(), tracker.options().min_reach_points);
  track(tracker, 2, 3.5, part);
  LabelledCloud walker;
  addPerson(walker, 1.5f, 2.0f);
  track(tracker, 3, 4.0, walker);
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].keyframes, (std::vector<std::uint64_t>{0, 1, 2}));
  EXPECT_EQ(tracks[1].keyframes, (std::vector<std::uint64_t>{0, 1, 3}));
}

// A person seen still and then out of view: a small person segment far away (a stray label, a
// partial view of someone else) does not continue their track across the reach of the absence;
// the person seen whole there does: they got up and walked.
TEST(DynamicObjectTracker, ASmallSegmentFarAwayDoesNotMoveAStillTrack) {
  DynamicObjectTracker tracker({});
  LabelledCloud seated;
  addPerson(seated, -1.0f, 4.0f);
  for (int k = 0; k < 3; ++k) track(tracker, static_cast<std::uint64_t>(k), 0.5 * k, seated);
  LabelledCloud stray;  // 2 m to the left of the seated person, 2.7 s after
  addBox(stray, {-3.0f, -1.2f, 4.0f}, {-2.9f, -1.1f, 4.1f}, SemanticClass::kPerson);
  ASSERT_GT(stray.size(), tracker.options().min_track_points);
  ASSERT_LT(stray.size(), tracker.options().min_reach_points);
  track(tracker, 3, 1.0 + 2.7, stray);
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].keyframes.size(), 3u);
  EXPECT_LT(tracks[0].travelled, 0.1f);
  LabelledCloud stood;  // the seated person, whole, 2 m to the right a second later
  addPerson(stood, 1.0f, 4.0f);
  track(tracker, 4, 1.0 + 2.7 + 1.0, stood);
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].keyframes.size(), 4u);
  EXPECT_GT(tracks[0].travelled, 1.9f);
}

// A walker seen in partial views whose centroids moved less than slack, but whose place a
// keyframe once showed empty, walks: a keyframe that does not see their last place (turned away)
// continues their track where they walked to. Taken for a seated person, a walker near the camera
// got a second track (h93: three tracks for two walkers).
TEST(DynamicObjectTracker, AWalkerWhoOnceLeftAPlaceIsFollowedWhereTheyWalk) {
  DynamicObjectTracker tracker({});
  LabelledCloud first;
  addPerson(first, 0.0f, 2.0f);
  track(tracker, 0, 0.0, first);
  track(tracker, 1, 0.5, LabelledCloud());  // their place seen empty
  LabelledCloud back;
  addPerson(back, 0.3f, 2.0f);
  track(tracker, 2, 1.0, back);
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 1u);
  ASSERT_LE(tracks[0].travelled, tracker.options().slack);
  ASSERT_TRUE(tracks[0].left_a_place);
  LabelledCloud walked;  // 1.2 m on, half a second later
  addPerson(walked, 1.5f, 2.0f);
  ASSERT_GE(walked.size(), tracker.options().min_reach_points);
  const auto segments = segmentByLabel(walked, tracker.options().cell_size, 50);
  tracker.addKeyFrame(3, 1.5, walked, segments, KeyFrameDepthView());
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_EQ(tracks[0].keyframes, (std::vector<std::uint64_t>{0, 2, 3}));
}

// The held-out composites' case: a seated person seen in one keyframe; 1.4 s later a walker steps
// in 2.5 m nearer the camera, in front of them, within the reach of a person who got up. The
// walker hides the place, so nothing shows the seated person gone: the walker is someone else.
TEST(DynamicObjectTracker, AWalkerInFrontOfASeatedPersonDoesNotTakeTheirTrack) {
  DynamicObjectTracker tracker({});
  LabelledCloud seated;
  addPerson(seated, -1.0f, 4.0f);
  track(tracker, 0, 0.0, seated);
  LabelledCloud walker_in_front;
  addPerson(walker_in_front, -0.5f, 1.5f);
  ASSERT_GE(walker_in_front.size(), tracker.options().min_reach_points);
  track(tracker, 1, 1.4, walker_in_front);
  LabelledCloud both;  // the walker stepped aside; the seated person is seen again
  addPerson(both, -1.0f, 4.0f);
  addPerson(both, -0.1f, 1.5f);
  track(tracker, 2, 1.8, both);
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].keyframes, (std::vector<std::uint64_t>{0, 2}));
  EXPECT_LT(tracks[0].travelled, 0.1f);
  EXPECT_FALSE(tracks[0].left_a_place);
  EXPECT_EQ(tracks[1].keyframes, (std::vector<std::uint64_t>{1, 2}));
}

// A larger person-labelled blob beside a seated person (their chair's back, a coat) joins their
// track by touching them; the person, whom the track follows, places it.
TEST(DynamicObjectTracker, ABlobJoiningASeatedPersonDoesNotMoveTheirTrack) {
  DynamicObjectTracker tracker({});
  LabelledCloud seated;
  addPerson(seated, -1.0f, 4.0f);
  track(tracker, 0, 0.0, seated);
  track(tracker, 1, 0.5, seated);
  LabelledCloud with_blob = seated;
  addBox(with_blob, {-2.3f, -1.7f, 4.0f}, {-1.2f, 0.0f, 4.3f}, SemanticClass::kPerson);
  track(tracker, 2, 1.0, with_blob);
  track(tracker, 3, 1.5, seated);
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_EQ(tracks[0].keyframes.size(), 4u);
  EXPECT_LT(tracks[0].travelled, 0.1f);
  // The blob stands where the first keyframes saw the wall; the seated person never did.
  EXPECT_FALSE(tracks[0].arrived);
}

// Walker 30 Hz: a walker out of view for 3 s; meanwhile the mask takes part of a chair 4 m away
// for a person. Within the walker's reach, but the keyframes before saw the chair there, and only
// one of them (its depth missing the chair) the room behind it: nobody walked there. It starts a
// track of its own, and the walker, back, continues theirs (taken by the chair, the walker came
// back as a second track).
TEST(DynamicObjectTracker, NoWalkerContinuesWhereAStaticThingStoodBefore) {
  DynamicObjectTracker tracker({});
  LabelledCloud room = backdrop();
  addBox(room, {-2.0f, -0.8f, 4.0f}, {-1.9f, -0.7f, 4.1f}, SemanticClass::kNone);
  for (int k = 0; k < 4; ++k) {
    LabelledCloud cloud;
    addPerson(cloud, 0.5f * static_cast<float>(k), 2.0f);
    track(tracker, static_cast<std::uint64_t>(k), 0.5 * k, cloud, k == 0 ? backdrop() : room);
  }
  const LabelledCloud chair_as_person =
      test_clouds::box({-2.0f, -0.8f, 4.0f}, {-1.9f, -0.7f, 4.1f}, SemanticClass::kPerson);
  ASSERT_GE(chair_as_person.size(), tracker.options().min_track_points);
  track(tracker, 4, 1.5 + 3.0, chair_as_person);
  LabelledCloud walker;
  addPerson(walker, 1.0f, 2.0f);
  track(tracker, 5, 1.5 + 3.5, walker);
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].keyframes, (std::vector<std::uint64_t>{0, 1, 2, 3, 5}));
  EXPECT_EQ(tracks[1].keyframes, (std::vector<std::uint64_t>{4}));
}

// s11 at 30 Hz: a walker seen in parts (under min_reach_points) comes within 0.4 m of where a
// "person" segment was seen 7 s before. 0.12 m from their own place of 0.37 s before, they keep
// their track (relative to each track's walking reach, the old one was nearer, and the walker
// came back as a second track).
TEST(DynamicObjectTracker, AWalkerSeenAMomentAgoNearbyKeepsTheirTrack) {
  DynamicObjectTracker tracker({});
  const auto part_at = [](float x) {
    return test_clouds::box({x - 0.075f, -0.925f, 2.125f}, {x + 0.075f, -0.775f, 2.175f},
                            SemanticClass::kPerson);
  };
  track(tracker, 0, 0.0,
        test_clouds::box({-0.05f, -0.9f, 2.1f}, {0.05f, -0.8f, 2.2f}, SemanticClass::kPerson));
  ASSERT_LT(part_at(0.0f).size(), tracker.options().min_reach_points);
  track(tracker, 1, 6.5, part_at(1.0f));
  track(tracker, 2, 7.0, part_at(0.52f));
  track(tracker, 3, 7.37, part_at(0.4f));
  const auto& tracks = tracker.tracks();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].keyframes, (std::vector<std::uint64_t>{0}));
  EXPECT_EQ(tracks[1].keyframes, (std::vector<std::uint64_t>{1, 2, 3}));
}

}  // namespace
}  // namespace segslam::dense
