#include "segslam/tracking/relocaliser.h"

#include <gtest/gtest.h>

#include "segslam/feature/orb_extractor.h"
#include "segslam/map/map.h"
#include "segslam/synth/sequence.h"
#include "segslam/testing/synth_sequences.h"
#include "segslam/testing/tracking_frames.h"

namespace segslam::tracking {
namespace {

// Keyframes of the synthetic room lap at their true poses, each with a map point for every
// keypoint with depth, and a later frame of the lap to relocalise.
class RelocaliserOnARoomLap : public ::testing::Test {
 protected:
  RelocaliserOnARoomLap() : sequence_(testing::noisyRoomLap(300)) {
    for (int index : {0, 2}) keyframes_.push_back(keyFrameAt(index));
  }

  map::Frame frameAt(int index) {
    return testing::trackingFrame(sequence_, index, extractor_, camera_);
  }

  std::shared_ptr<map::KeyFrame> keyFrameAt(int index) {
    map::Frame frame = frameAt(index);
    frame.T_cw = sequence_.cameraPose(index).inverse();
    frame.has_pose = true;
    auto keyframe = map_.createKeyFrame(frame);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (frame.depth[i] <= 0.0f) continue;
      auto point = map_.createMapPoint(keyframe->unproject(i), keyframe.get());
      point->addObservation(keyframe.get(), i);
      keyframe->addMapPoint(point, i);
      point->updateDescriptor();
      point->updateNormalAndDepth();
    }
    return keyframe;
  }

  static double metresFrom(const geometry::Pose& T_cw, const geometry::Pose& T_wc_true) {
    return (T_cw.inverse().translation() - T_wc_true.translation()).norm();
  }

  synth::SyntheticSequence sequence_;
  feature::OrbExtractor extractor_;
  std::shared_ptr<const map::FrameCamera> camera_ = std::make_shared<map::FrameCamera>(
      sequence_.camera(), map::kDefaultVirtualBaselineM, 40.0, feature::ScaleLevels(8, 1.2));
  map::Map map_;
  std::vector<std::shared_ptr<map::KeyFrame>> keyframes_;
};

TEST_F(RelocaliserOnARoomLap, PlacesTheFrameOnTheFirstCandidateThatIsAccepted) {
  map::Frame frame = frameAt(4);
  int asked = 0;
  const auto pose = relocaliseAgainstKeyFrames(frame, keyframes_, [&](const geometry::Pose&) {
    ++asked;
    return true;
  });
  ASSERT_TRUE(pose.has_value());
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(frame.reference_keyframe, keyframes_[0]);
  EXPECT_LT(metresFrom(*pose, sequence_.cameraPose(4)), 0.05);
}

// A candidate whose pose the caller refuses (its points not checked by an own mask, say) leaves
// the others to be tried: the frame is placed by the next one.
TEST_F(RelocaliserOnARoomLap, TriesTheNextCandidateWhenOneIsRefused) {
  map::Frame frame = frameAt(4);
  std::vector<std::shared_ptr<map::KeyFrame>> asked;
  const auto pose = relocaliseAgainstKeyFrames(frame, keyframes_, [&](const geometry::Pose&) {
    asked.push_back(frame.reference_keyframe);
    return frame.reference_keyframe != keyframes_[0];
  });
  ASSERT_TRUE(pose.has_value());
  EXPECT_EQ(asked, keyframes_);
  EXPECT_EQ(frame.reference_keyframe, keyframes_[1]);
  EXPECT_LT(metresFrom(*pose, sequence_.cameraPose(4)), 0.05);
  int matched = 0;
  for (const auto& point : frame.map_points) {
    if (!point) continue;
    ++matched;
    EXPECT_TRUE(point->isObservedBy(keyframes_[1].get()));
  }
  EXPECT_GE(matched, 30);
}

TEST_F(RelocaliserOnARoomLap, NoPoseWhenEveryCandidateIsRefused) {
  map::Frame frame = frameAt(4);
  int asked = 0;
  const auto pose = relocaliseAgainstKeyFrames(frame, keyframes_, [&](const geometry::Pose&) {
    ++asked;
    return false;
  });
  EXPECT_FALSE(pose.has_value());
  EXPECT_EQ(asked, 2);
  for (const auto& point : frame.map_points) EXPECT_EQ(point, nullptr);
}

}  // namespace
}  // namespace segslam::tracking
