#include "segslam/system/slam_system.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "segslam/io/tum_dataset.h"
#include "segslam/testing/synth_sequences.h"
#include "segslam/testing/test_support.h"

namespace segslam::system {
namespace {

struct KidnapResult {
  int lost_after_jump = 0;
  double jump_pose_error_m = 1e9;  // first frame after the jump, against the ground truth
};

// A camera picked up and put down elsewhere: a lap around the synthetic room (320x240,
// Kinect-like depth noise) played up to frame 200, where it looks at the far side of the room,
// then again from frame 20, whose place only the map's first keyframes saw. Carrying it there
// takes `carried_s` seconds, in which no frame arrives.
KidnapResult playKidnappedLap(const io::TumDataset& lap, SlamOptions options,
                              double carried_s = 2.0) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < 200; ++i) order.push_back(i);
  for (std::size_t i = 20; i < 60; ++i) order.push_back(i);
  options.deterministic = true;
  options.loop_closing = false;
  SlamSystem slam(lap.camera(), options);
  KidnapResult result;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto frame =
        lap.loadFrame(order[k], {.mask = false, .labels = false, .instances = false});
    const double timestamp = static_cast<double>(k) / 30.0 + (k >= 200 ? carried_s : 0.0);
    const auto stats = slam.processFrame(timestamp, frame.rgb, frame.depth, {});
    if (k >= 200 && stats.state != tracking::TrackingState::kOk) ++result.lost_after_jump;
  }
  slam.finish();
  const auto estimate = slam.cameraTrajectory();
  const auto& truth = *lap.groundTruth();
  const auto first = estimate.poseAt(0.0);
  const auto jumped = estimate.poseAt(200.0 / 30.0 + carried_s);
  if (first && jumped) {
    const geometry::Pose truth_first = *truth.poseAt(lap.frames()[0].timestamp);
    const geometry::Pose truth_jumped = *truth.poseAt(lap.frames()[20].timestamp);
    const geometry::Pose estimated = first->inverse() * *jumped;
    const geometry::Pose expected = truth_first.inverse() * truth_jumped;
    result.jump_pose_error_m = (estimated.translation() - expected.translation()).norm();
  }
  return result;
}

TEST(SlamSystem, RelocalisesACameraCarriedToAPlaceSeenLongBefore) {
  const auto dataset = io::TumDataset::open(testing::sharedSequence(testing::noisyRoomLap(300)));

  SlamOptions with_vocabulary;
  with_vocabulary.relocalisation_vocabulary =
      std::make_shared<const place::Vocabulary>(place::Vocabulary::load(
          std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config" / place::kDefaultVocabularyFile));
  const auto found = playKidnappedLap(dataset, with_vocabulary);
  EXPECT_EQ(found.lost_after_jump, 0);
  EXPECT_LT(found.jump_pose_error_m, 0.05);

  // The most recent keyframes alone do not see frame 20's place: tracking stays lost for a while,
  // so it is the bag of words that finds the place. Five of them: with crowded keyframes culled
  // the lap keeps fewer keyframes, and the default fifteen most recent reach frame 20's place.
  SlamOptions recent_only_options;
  recent_only_options.tracker.relocalisation_recent_keyframes = 5;
  const auto recent_only = playKidnappedLap(dataset, recent_only_options);
  EXPECT_GE(recent_only.lost_after_jump, 10);
}

// The same place 1/30 s after the last tracked frame is farther than a camera can have gone
// (tracking::MotionLimitOptions): the frames stay lost, however well they match, until enough
// time has passed for the camera to have been carried there.
TEST(SlamSystem, DoesNotRelocaliseWhereTheCameraCannotHaveGone) {
  const auto dataset = io::TumDataset::open(testing::sharedSequence(testing::noisyRoomLap(300)));
  SlamOptions options;
  options.relocalisation_vocabulary =
      std::make_shared<const place::Vocabulary>(place::Vocabulary::load(
          std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config" / place::kDefaultVocabularyFile));
  const auto teleported = playKidnappedLap(dataset, options, 0.0);
  EXPECT_GE(teleported.lost_after_jump, 5);
  EXPECT_GT(teleported.jump_pose_error_m, 1e8);  // the first frame after the jump has no pose
}

// A mask that covers the whole view for a second (a network output carried on after the people
// it marked had left): no frame under it has a keypoint outside it, so each is tried again on
// the whole image, where tracking searches only the map's static points.
TEST(SlamSystem, AFrameTheMaskLosesIsTriedWithoutIt) {
  const auto dataset = io::TumDataset::open(testing::sharedSequence(testing::noisyRoomLap(300)));
  SlamOptions options;
  options.deterministic = true;
  options.loop_closing = false;
  SlamSystem slam(dataset.camera(), options);
  std::vector<tracking::TrackingState> states;
  for (std::size_t i = 0; i < 150; ++i) {
    const auto frame = dataset.loadFrame(i, {.mask = false, .labels = false, .instances = false});
    const cv::Mat stale_mask =
        i >= 120 ? cv::Mat(frame.rgb.size(), CV_8UC1, cv::Scalar(255)) : cv::Mat();
    states.push_back(
        slam.processFrame(static_cast<double>(i) / 30.0, frame.rgb, frame.depth, stale_mask).state);
  }
  for (std::size_t i = 119; i < states.size(); ++i) {
    EXPECT_EQ(states[i], tracking::TrackingState::kOk) << "frame " << i;
  }
}

}  // namespace
}  // namespace segslam::system
