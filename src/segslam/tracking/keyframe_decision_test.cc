#include "segslam/tracking/keyframe_decision.h"

#include <gtest/gtest.h>

namespace segslam::tracking {
namespace {

constexpr std::uint64_t kFirst = 3;
constexpr std::uint64_t kSecond = 4;

TEST(ReferenceOverlap, ShareIsAgainstTheMostTrackedSinceTheReferenceCame) {
  ReferenceOverlap overlap;
  overlap.update(kFirst, 300);
  overlap.update(kFirst, 400);
  overlap.update(kFirst, 280);
  EXPECT_EQ(overlap.best(), 400);
  EXPECT_DOUBLE_EQ(overlap.share(), 0.7);
}

// An old keyframe that becomes the reference again is measured from its new first frame, not from
// a best frame whose points may have been culled since.
TEST(ReferenceOverlap, ANewReferenceRestartsTheYardstick) {
  ReferenceOverlap overlap;
  overlap.update(kFirst, 500);
  overlap.update(kSecond, 200);
  EXPECT_DOUBLE_EQ(overlap.share(), 1.0);
  overlap.update(kFirst, 250);
  EXPECT_EQ(overlap.best(), 250);
}

TEST(ReferenceOverlap, NothingTrackedYetIsAFullShare) {
  EXPECT_DOUBLE_EQ(ReferenceOverlap().share(), 1.0);
}

KeyFrameEvidence steadyFrame() {
  KeyFrameEvidence evidence;
  evidence.inliers = 300;
  evidence.tracked_share = 0.9;
  evidence.tracked_close = 250;
  evidence.untracked_close = 200;
  evidence.frames_since_keyframe = 5;
  return evidence;
}

TEST(NeedsKeyFrame, NotWhileTheFrameStillTracksMostOfTheReference) {
  EXPECT_FALSE(needsKeyFrame(steadyFrame(), {}));
}

TEST(NeedsKeyFrame, WhenTheTrackedShareFallsBelowTheRatio) {
  KeyFrameEvidence evidence = steadyFrame();
  evidence.tracked_share = 0.7;
  EXPECT_TRUE(needsKeyFrame(evidence, {}));
}

TEST(NeedsKeyFrame, WhenFewClosePointsAreTrackedAndManyAreNew) {
  KeyFrameEvidence evidence = steadyFrame();
  evidence.tracked_close = 90;
  evidence.untracked_close = 80;
  EXPECT_TRUE(needsKeyFrame(evidence, {}));
  evidence.untracked_close = 60;
  EXPECT_FALSE(needsKeyFrame(evidence, {}));
}

TEST(NeedsKeyFrame, TheTimeoutForcesOneWhateverTheShare) {
  KeyFrameEvidence evidence = steadyFrame();
  evidence.frames_since_keyframe = 30;
  EXPECT_TRUE(needsKeyFrame(evidence, {}));
}

TEST(NeedsKeyFrame, ABusyMapperTakesOnlyAWeakFrame) {
  KeyFrameEvidence evidence = steadyFrame();
  evidence.mapping_idle = false;
  evidence.queued_keyframes = 1;
  evidence.tracked_share = 0.7;
  EXPECT_FALSE(needsKeyFrame(evidence, {}));
  evidence.tracked_share = 0.2;
  EXPECT_TRUE(needsKeyFrame(evidence, {}));
  evidence.queued_keyframes = 3;
  EXPECT_FALSE(needsKeyFrame(evidence, {}));
}

TEST(NeedsKeyFrame, NeverWithTooFewInliersForATrustworthyPose) {
  KeyFrameEvidence evidence = steadyFrame();
  evidence.tracked_share = 0.1;
  evidence.frames_since_keyframe = 100;
  evidence.inliers = 15;
  EXPECT_FALSE(needsKeyFrame(evidence, {}));
}

// A frame held by few checked points may be held by a person the masks missed: a keyframe would
// put its new points on him.
TEST(NeedsKeyFrame, NeverOnAFrameFewCheckedPointsHold) {
  KeyFrameEvidence evidence = steadyFrame();
  evidence.tracked_share = 0.2;
  evidence.inliers = 70;
  evidence.local_map_checked = true;
  evidence.checked_inliers = 15;
  EXPECT_FALSE(needsKeyFrame(evidence, {}));
  evidence.checked_inliers = 20;
  EXPECT_TRUE(needsKeyFrame(evidence, {}));
}

// Before the first keyframe's own mask comes, every point is provisional: the map must grow.
TEST(NeedsKeyFrame, BeforeAnyPointIsCheckedTheMapStillGrows) {
  KeyFrameEvidence evidence = steadyFrame();
  evidence.tracked_share = 0.2;
  evidence.checked_inliers = 0;
  evidence.local_map_checked = false;
  EXPECT_TRUE(needsKeyFrame(evidence, {}));
}

}  // namespace
}  // namespace segslam::tracking
