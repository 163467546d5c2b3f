#include "segslam/tracking/tracker.h"

#include <gtest/gtest.h>

#include <mutex>

#include "segslam/feature/orb_extractor.h"
#include "segslam/synth/sequence.h"
#include "segslam/testing/synth_sequences.h"
#include "segslam/testing/tracking_frames.h"

namespace segslam::tracking {
namespace {

// A local mapper that maps nothing and is three keyframes behind, so that tracking makes no
// keyframe after the first: the test decides what local mapping would have done.
class BusyMapper : public KeyFrameSink {
 public:
  void insertKeyFrame(std::shared_ptr<map::KeyFrame> keyframe) override {
    keyframes.push_back(std::move(keyframe));
  }
  [[nodiscard]] bool isIdle() const override { return false; }
  [[nodiscard]] std::size_t queuedKeyFrames() const override { return 3; }

  std::vector<std::shared_ptr<map::KeyFrame>> keyframes;
};

// The first frames of the synthetic room lap, made into tracking frames as SlamSystem makes them.
class TrackerOnARoomLap : public ::testing::Test {
 protected:
  TrackerOnARoomLap() : sequence_(testing::noisyRoomLap(300)) {}

  map::Frame frameAt(int index) {
    return testing::trackingFrame(sequence_, index, extractor_, camera_);
  }

  TrackingResult track(Tracker& tracker, int index) {
    map::Frame frame = frameAt(index);
    std::lock_guard lock(map_.mutex);
    return tracker.track(std::move(frame));
  }

  // Tracks the lap's first `count` frames, each of which must be tracked.
  void trackFirst(Tracker& tracker, int count) {
    for (int index = 0; index < count; ++index) {
      ASSERT_EQ(track(tracker, index).state, TrackingState::kOk) << "frame " << index;
    }
  }

  // Frame `index` with its depth but no keypoint: as a mask covering the whole view leaves it.
  map::Frame keypointlessFrame(int index) {
    return map::Frame(static_cast<std::uint64_t>(index), sequence_.timestamp(index), {}, cv::Mat(),
                      frameAt(index).depth_image, cv::Mat(), camera_);
  }

  // Frame `index` with `count` of its keypoints, spread over the image: enough for the motion
  // model, too few for the local map.
  map::Frame sparseFrame(int index, int count) {
    const map::Frame whole = frameAt(index);
    const std::size_t stride = whole.size() / static_cast<std::size_t>(count);
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
    for (std::size_t i = 0; keypoints.size() < static_cast<std::size_t>(count); i += stride) {
      keypoints.push_back(whole.keypoints[i]);
      descriptors.push_back(whole.descriptors.row(static_cast<int>(i)));
    }
    return map::Frame(static_cast<std::uint64_t>(index), sequence_.timestamp(index),
                      std::move(keypoints), descriptors, whole.depth_image, cv::Mat(), camera_);
  }

  synth::SyntheticSequence sequence_;
  feature::OrbExtractor extractor_;
  std::shared_ptr<const map::FrameCamera> camera_ = std::make_shared<map::FrameCamera>(
      sequence_.camera(), map::kDefaultVirtualBaselineM, 40.0, feature::ScaleLevels(8, 1.2));
  map::Map map_;
  BusyMapper sink_;
};

// Local mapping may cull the keyframes that observe a frame's points while the frame waits to be
// tracked (or its points may all be visual-odometry points, observed by none): no keyframe wins
// the local map's vote for the frame's reference. It keeps the tracker's reference then, so that
// its pose is recorded and resolved like any other.
TEST_F(TrackerOnARoomLap, FrameWhosePointsNoLiveKeyFrameObservesIsRecordedAgainstTheLastReference) {
  Tracker tracker(map_, sink_);
  ASSERT_NO_FATAL_FAILURE(trackFirst(tracker, 4));
  const map::KeyFrame* last_reference = tracker.frameRecords().back().reference;
  const std::size_t records = tracker.frameRecords().size();
  for (const auto& keyframe : map_.keyFrames()) keyframe->bad = true;

  const TrackingResult result = track(tracker, 4);

  ASSERT_EQ(result.state, TrackingState::kOk);
  EXPECT_FALSE(result.new_keyframe);
  ASSERT_EQ(tracker.frameRecords().size(), records + 1);
  EXPECT_EQ(tracker.frameRecords().back().reference, last_reference);
  EXPECT_EQ(tracker.currentFrame().reference_keyframe.get(), last_reference);
}

// A frame that lost track among people is relocalised only by points a keyframe's own mask has
// checked: those no mask has checked yet (MapPoint::provisional) may lie on a person the carried
// masks missed, and would place the camera by him.
TEST_F(TrackerOnARoomLap, RelocalisesOnlyOnPointsAnOwnMaskHasChecked) {
  Tracker tracker(map_, sink_);
  ASSERT_NO_FATAL_FAILURE(trackFirst(tracker, 3));
  // A frame without features loses track; the next one, as the camera comes back, must be
  // relocalised (the motion model is gone).
  {
    std::lock_guard lock(map_.mutex);
    ASSERT_EQ(tracker.track(keypointlessFrame(3)).state, TrackingState::kLost);
  }
  // The map's points are all provisional: no keyframe's own mask has been applied.
  EXPECT_EQ(track(tracker, 4).state, TrackingState::kLost);

  for (const auto& point : map_.mapPoints()) point->provisional = false;
  EXPECT_EQ(track(tracker, 5).state, TrackingState::kOk);
}

// A stale dynamic mask can leave a frame nothing to track (people9 of bench/soak.sh: a network
// output carried on after both walkers left covers the desk): the frame is tried again on the
// whole image before the camera is called lost.
TEST_F(TrackerOnARoomLap, AFrameTheMaskLeavesNothingToTrackIsTriedOnTheWholeImage) {
  Tracker tracker(map_, sink_);
  ASSERT_NO_FATAL_FAILURE(trackFirst(tracker, 4));
  std::lock_guard lock(map_.mutex);
  const TrackingResult result = tracker.track(keypointlessFrame(4), [this] { return frameAt(4); });
  EXPECT_EQ(result.state, TrackingState::kOk);
  EXPECT_GT(tracker.currentFrame().size(), 0u);
  EXPECT_EQ(tracker.frameRecords().size(), 5u);
}

// The frame's first placement searched the local map and fell short; the whole-image frame,
// with the same frame number, must get a local map of its own to search.
TEST_F(TrackerOnARoomLap, AFrameTriedAgainSearchesTheWholeLocalMapAgain) {
  Tracker tracker(map_, sink_);
  ASSERT_NO_FATAL_FAILURE(trackFirst(tracker, 4));
  const std::size_t local_points = tracker.localMapPoints();
  ASSERT_GT(local_points, 0u);
  std::lock_guard lock(map_.mutex);
  const TrackingResult result = tracker.track(sparseFrame(4, 46), [this] { return frameAt(4); });
  EXPECT_EQ(result.state, TrackingState::kOk);
  EXPECT_EQ(tracker.localMapPoints(), local_points);
}

TEST(FramePoseRecord, GivesBackThePoseItWasMadeWith) {
  geometry::Pose T_c_reference = geometry::Pose::Identity();
  T_c_reference.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -1.0, 0.4).normalized()).toRotationMatrix();
  T_c_reference.translation() = Eigen::Vector3d(1.25, -0.5, 3.0);
  const Tracker::FramePoseRecord record(2.0, nullptr, T_c_reference);
  EXPECT_TRUE(record.T_c_reference().isApprox(T_c_reference, 1e-12));
}

}  // namespace
}  // namespace segslam::tracking
