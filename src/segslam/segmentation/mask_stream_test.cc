#include "segslam/segmentation/mask_stream.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <thread>
#include <vector>

#include "segslam/testing/test_support.h"

namespace segslam::segmentation {
namespace {

SemanticSegmenter espnet() {
  const auto config_file =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";
  return SemanticSegmenter(readModelConfig(config_file),
                           *testing::sharedDir() / "models" / "espnetv2_voc_384.onnx");
}

Segment espnetSegment() {
  auto segmenter = std::make_shared<SemanticSegmenter>(espnet());
  return [segmenter](const SegmentationJob& job) { return segmenter->segment(job.current.bgr); };
}

TEST(MaskStream, EveryFrameGetsAMaskWithoutWaitingForTheNetwork) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  const cv::Mat bgr = cv::imread((frames / "rgb" / "1341846313.592026.png").string());
  ASSERT_FALSE(bgr.empty());
  SemanticSegmenter direct = espnet();
  const SemanticMasks expected = direct.segment(bgr);
  const MaskStreamOptions options;
  cv::Mat grown_limit;
  // Masks are carried at the flow's half resolution: an outline may move by one pixel, and the
  // discrete discs of the growth and of this check differ by another.
  const int limit = options.max_growth_px + 2;
  cv::dilate(expected.dynamic, grown_limit,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * limit + 1, 2 * limit + 1)));
  MaskStream stream(espnetSegment(), options);
  for (std::uint64_t frame = 0; frame < 12; ++frame) {
    const SemanticMasks masks = stream.masksFor(frame, bgr, cv::Mat());
    ASSERT_EQ(masks.dynamic.size(), bgr.size()) << frame;
    ASSERT_EQ(masks.labels.size(), bgr.size()) << frame;
    // The camera does not move, so whichever output the frame gets, it covers the first
    // frame's, grown by at most the options' limit as it ages.
    EXPECT_LT(cv::countNonZero(expected.dynamic & ~masks.dynamic), 0.01 * bgr.total()) << frame;
    EXPECT_EQ(cv::countNonZero(masks.dynamic & ~grown_limit), 0) << frame;
  }
  // The first frame waits for its own output; later frames only take what is finished.
  EXPECT_GE(stream.runs(), 1);
  EXPECT_LT(stream.runs(), 12);
}

TEST(MaskStream, SynchronousModeRunsTheNetworkEveryIntervalFrames) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  const cv::Mat bgr = cv::imread((frames / "rgb" / "1341846316.570121.png").string());
  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = 4;
  MaskStream stream(espnetSegment(), options);
  for (std::uint64_t frame = 0; frame < 9; ++frame) {
    EXPECT_GT(cv::countNonZero(stream.masksFor(frame, bgr, cv::Mat()).dynamic), 0) << frame;
  }
  EXPECT_EQ(stream.runs(), 3);  // frames 0, 4 and 8
}

// A segmenter that marks nothing and records the frames it was given.
struct RecordedJobs {
  std::mutex mutex;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> previous_and_current;
};

Segment recordingSegment(const std::shared_ptr<RecordedJobs>& record) {
  return [record](const SegmentationJob& job) {
    std::lock_guard lock(record->mutex);
    record->previous_and_current.emplace_back(job.previous.id, job.current.id);
    return SemanticMasks{};
  };
}

TEST(MaskStream, SynchronousSegmenterGetsEachFrameWithTheOneBefore) {
  auto record = std::make_shared<RecordedJobs>();
  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = 1;
  MaskStream stream(recordingSegment(record), options);
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  for (std::uint64_t frame = 1; frame <= 4; ++frame) {
    const SemanticMasks masks = stream.masksFor(frame, bgr, cv::Mat());
    EXPECT_EQ(masks.dynamic.size(), bgr.size());
    EXPECT_EQ(cv::countNonZero(masks.dynamic), 0);
  }
  const std::vector<std::pair<std::uint64_t, std::uint64_t>> expected = {
      {0, 1}, {1, 2}, {2, 3}, {3, 4}};
  EXPECT_EQ(record->previous_and_current, expected);
}

// Marks as many pixels of the first row as the frame's id plus one, so outputs tell their frame.
Segment countingSegment() {
  return [](const SegmentationJob& job) {
    cv::Mat dynamic = cv::Mat::zeros(job.current.bgr.size(), CV_8UC1);
    dynamic(cv::Rect(0, 0, static_cast<int>(job.current.id) + 1, 1)) = 255;
    return SemanticMasks{dynamic, dynamic};
  };
}

// Synchronous, the network on every 4th frame, its outputs `latency_frames` frames late.
MaskStreamOptions everyFourthFrame(int latency_frames) {
  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = 4;
  options.latency_frames = latency_frames;
  return options;
}

TEST(MaskStream, SynchronousLatencyDeliversOutputsLateAndReportsThem) {
  MaskStream stream(countingSegment(), everyFourthFrame(2));
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  std::vector<std::uint64_t> late_frames;
  for (std::uint64_t frame = 0; frame < 10; ++frame) {
    static_cast<void>(stream.masksFor(frame, bgr, cv::Mat()));
    for (const LateOutput& late : stream.takeLateOutputs()) {
      EXPECT_EQ(late.frame_id + 2, frame);
      EXPECT_EQ(cv::countNonZero(late.dynamic), static_cast<int>(late.frame_id) + 1);
      EXPECT_FALSE(late.keyframe);
      late_frames.push_back(late.frame_id);
    }
    EXPECT_TRUE(stream.takeLateOutputs().empty()) << "taken once";
  }
  // Frame 0's output is used at once (the first frame waits); frame 8's is not due before 10.
  EXPECT_EQ(late_frames, std::vector<std::uint64_t>{4});
  EXPECT_EQ(stream.runs(), 3);
}

// Keyframe outputs taken from the stream over frames [first, last), by the frame they came with.
std::vector<std::pair<std::uint64_t, std::uint64_t>> keyFrameOutputs(MaskStream& stream,
                                                                     std::uint64_t first,
                                                                     std::uint64_t last,
                                                                     const cv::Mat& bgr) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> outputs;
  for (std::uint64_t frame = first; frame < last; ++frame) {
    static_cast<void>(stream.masksFor(frame, bgr, cv::Mat()));
    for (const LateOutput& late : stream.takeLateOutputs()) {
      if (!late.keyframe) continue;
      EXPECT_EQ(cv::countNonZero(late.dynamic), static_cast<int>(late.frame_id) + 1);
      outputs.emplace_back(late.frame_id, frame);
    }
  }
  return outputs;
}

TEST(MaskStream, SynchronousKeyFrameOutputComesBackOnceAfterTheLatency) {
  MaskStream stream(countingSegment(), everyFourthFrame(2));
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  ASSERT_TRUE(keyFrameOutputs(stream, 0, 6, bgr).empty());
  stream.segmentKeyFrame(5, bgr, cv::Mat());  // frame 5 is handed on; the network was not due
  const auto outputs = keyFrameOutputs(stream, 6, 12, bgr);
  ASSERT_EQ(outputs.size(), 1u);
  EXPECT_EQ(outputs[0], std::make_pair(std::uint64_t{5}, std::uint64_t{7}));
  // Frames 0 and 4 as scheduled, the keyframe 5, then 9: the schedule counts from the keyframe.
  EXPECT_EQ(stream.runs(), 4);
}

TEST(MaskStream, AKeyFrameWhoseOutputIsThereAlreadyIsNotSegmentedAgain) {
  MaskStream stream(countingSegment(), everyFourthFrame(0));
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  static_cast<void>(keyFrameOutputs(stream, 0, 5, bgr));  // runs on frames 0 and 4
  stream.segmentKeyFrame(4, bgr, cv::Mat());
  const auto outputs = keyFrameOutputs(stream, 5, 6, bgr);
  ASSERT_EQ(outputs.size(), 1u);
  EXPECT_EQ(outputs[0].first, 4u);
  EXPECT_EQ(stream.runs(), 2);
}

// Segments only when allowed to, so that a test can queue jobs behind a busy segmenter; records
// the order in which it was given the frames.
struct GatedSegmenter {
  std::mutex mutex;
  std::condition_variable changed;
  int allowed = 0;
  std::vector<std::uint64_t> order;

  void allow(int runs) {
    {
      std::lock_guard lock(mutex);
      allowed += runs;
    }
    changed.notify_all();
  }

  void waitUntilGiven(std::size_t frames) {
    std::unique_lock lock(mutex);
    changed.wait(lock, [&] { return order.size() >= frames; });
  }
};

Segment gatedSegment(const std::shared_ptr<GatedSegmenter>& gate) {
  return [gate](const SegmentationJob& job) {
    {
      std::unique_lock lock(gate->mutex);
      gate->order.push_back(job.current.id);
      gate->changed.notify_all();
      gate->changed.wait(lock, [&] { return gate->allowed > 0; });
      --gate->allowed;
    }
    return countingSegment()(job);
  };
}

TEST(MaskStream, KeyFramesAreSegmentedBeforeNewerFrames) {
  auto gate = std::make_shared<GatedSegmenter>();
  MaskStream stream(gatedSegment(gate));
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  gate->allow(1);
  static_cast<void>(stream.masksFor(0, bgr, cv::Mat()));  // waits for frame 0's output
  static_cast<void>(stream.masksFor(1, bgr, cv::Mat()));  // frame 1 goes to the segmenter
  gate->waitUntilGiven(2);
  stream.segmentKeyFrame(0, bgr, cv::Mat());              // there already: back at once
  stream.segmentKeyFrame(1, bgr, cv::Mat());              // on its way: not queued twice
  static_cast<void>(stream.masksFor(2, bgr, cv::Mat()));  // segmenter busy: not queued
  stream.segmentKeyFrame(2, bgr, cv::Mat());              // queued first
  gate->allow(2);
  std::vector<std::uint64_t> keyframes;
  for (std::uint64_t frame = 3; frame < 200 && keyframes.size() < 3; ++frame) {
    static_cast<void>(stream.masksFor(frame, bgr, cv::Mat()));
    for (const LateOutput& late : stream.takeLateOutputs()) {
      if (late.keyframe) keyframes.push_back(late.frame_id);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(keyframes, (std::vector<std::uint64_t>{0, 1, 2}));
  gate->allow(1000);
  std::lock_guard lock(gate->mutex);
  ASSERT_GE(gate->order.size(), 3u);
  EXPECT_EQ(gate->order[1], 1u);
  EXPECT_EQ(gate->order[2], 2u) << "the keyframe comes before frame 3 and later ones";
}

TEST(MaskStream, ASegmenterThatCannotKeepUpGivesUpTheOldestKeyFrames) {
  auto gate = std::make_shared<GatedSegmenter>();
  MaskStreamOptions options;
  options.max_queued_keyframes = 2;
  MaskStream stream(gatedSegment(gate), options);
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  gate->allow(1);
  static_cast<void>(stream.masksFor(0, bgr, cv::Mat()));  // waits for frame 0's output
  static_cast<void>(stream.masksFor(1, bgr, cv::Mat()));  // frame 1 goes to the segmenter
  gate->waitUntilGiven(2);
  for (std::uint64_t keyframe = 2; keyframe < 8; ++keyframe) {
    static_cast<void>(stream.masksFor(keyframe, bgr, cv::Mat()));
    stream.segmentKeyFrame(keyframe, bgr, cv::Mat());
  }
  gate->allow(1000);
  std::vector<std::uint64_t> keyframes;
  for (std::uint64_t frame = 8; frame < 200 && keyframes.size() < 2; ++frame) {
    static_cast<void>(stream.masksFor(frame, bgr, cv::Mat()));
    for (const LateOutput& late : stream.takeLateOutputs()) {
      if (late.keyframe) keyframes.push_back(late.frame_id);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(keyframes, (std::vector<std::uint64_t>{6, 7}));
}

// Frame 0: an object at the left edge. Frames 1-3: the segmenter cannot tell (empty mask).
// Frame 4 and later: it sees nothing moving (all-zero mask).
Segment unsureAfterTheFirstFrame() {
  return [](const SegmentationJob& job) {
    if (job.current.id >= 1 && job.current.id <= 3) return SemanticMasks{};
    cv::Mat dynamic = cv::Mat::zeros(job.current.bgr.size(), CV_8UC1);
    if (job.current.id == 0) dynamic(cv::Rect(0, 0, 20, 20)) = 255;
    return SemanticMasks{dynamic, dynamic};
  };
}

TEST(MaskStream, AnUndecidedOutputKeepsTheObjectsOfTheOneBefore) {
  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = 1;
  MaskStream stream(unsureAfterTheFirstFrame(), options);
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  for (std::uint64_t frame = 0; frame <= 3; ++frame) {
    EXPECT_GE(cv::countNonZero(stream.masksFor(frame, bgr, cv::Mat()).dynamic), 20 * 20) << frame;
    EXPECT_TRUE(stream.takeLateOutputs().empty());
  }
  EXPECT_EQ(cv::countNonZero(stream.masksFor(4, bgr, cv::Mat()).dynamic), 0);
  EXPECT_EQ(stream.runs(), 5);
}

// Frames 0-2: an object in `box`; frame 3 and later: the segmenter sees nothing.
Segment objectUntilFrameTwo(cv::Rect box) {
  return [box](const SegmentationJob& job) {
    cv::Mat dynamic = cv::Mat::zeros(job.current.bgr.size(), CV_8UC1);
    if (job.current.id <= 2) dynamic(box) = 255;
    return SemanticMasks{dynamic, dynamic};
  };
}

// Non-zero pixels of each frame's mask, frames 0-9, of a still camera before a wall 3 m away
// with whatever `near` covers at 1 m (from frame 3 on: `near_later`).
std::vector<int> maskAreas(Segment segment, cv::Rect near, int linger_frames,
                           std::optional<cv::Rect> near_later = std::nullopt) {
  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = 1;
  options.border_linger_frames = linger_frames;
  MaskStream stream(std::move(segment), options);
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  cv::Mat depth(48, 64, CV_32FC1, cv::Scalar(3.0f));
  depth(near) = 1.0f;
  std::vector<int> areas;
  for (std::uint64_t frame = 0; frame < 10; ++frame) {
    if (frame == 3 && near_later) {
      depth.setTo(3.0f);
      depth(*near_later) = 1.0f;
    }
    areas.push_back(cv::countNonZero(stream.masksFor(frame, bgr, depth).dynamic));
  }
  return areas;
}

// A person cut down to a strip by the image border is no longer recognised: the strip stays in
// the masks for border_linger_frames frames after the last output that showed it (frame 2).
TEST(MaskStream, AnObjectLostAtTheBorderLingersForAWhile) {
  const cv::Rect strip(0, 10, 12, 30);
  const auto areas = maskAreas(objectUntilFrameTwo(strip), strip, 5);
  for (std::size_t frame = 0; frame <= 7; ++frame) EXPECT_GE(areas[frame], 12 * 30) << frame;
  EXPECT_EQ(areas[8], 0);
  EXPECT_EQ(areas[9], 0);
  EXPECT_EQ(maskAreas(objectUntilFrameTwo(strip), strip, 0)[3], 0) << "off";
}

TEST(MaskStream, AnObjectLostInsideTheImageDoesNotLinger) {
  const cv::Rect box(20, 10, 12, 30);
  const auto areas = maskAreas(objectUntilFrameTwo(box), box, 5);
  EXPECT_GE(areas[2], 12 * 30);
  EXPECT_EQ(areas[3], 0);
}

// From frame 3 on the strip's depth belongs to a surface three times its width (the person has
// gone, and the desk he stood in front of is at his depth): the strip snapped to depth would
// spread over the desk, and is dropped.
TEST(MaskStream, ALostObjectThatSpreadsOverALargerSurfaceIsDropped) {
  const cv::Rect strip(0, 10, 12, 30);
  const auto areas = maskAreas(objectUntilFrameTwo(strip), strip, 5, cv::Rect(0, 0, 36, 48));
  EXPECT_GE(areas[3], 12 * 30);
  EXPECT_EQ(areas[4], 0);
}

// An object in `box` on frame 0's output only (the network's next output is far off).
Segment objectOnFrameZero(cv::Rect box) {
  return [box](const SegmentationJob& job) {
    cv::Mat dynamic = cv::Mat::zeros(job.current.bgr.size(), CV_8UC1);
    if (job.current.id == 0) dynamic(box) = 255;
    return SemanticMasks{dynamic, dynamic};
  };
}

// A person leaning over the camera comes from 0.40 to 0.265 m in nine frames, more than the 20 %
// by which a region may differ from an object's depth: measured against frame 0's output by that
// share alone, the carried mask dropped him from frame 6 on as uncovered background.
TEST(MaskStream, ACarriedMaskKeepsAPersonComingTowardsTheCamera) {
  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = 100;
  const cv::Rect person(16, 8, 24, 32);
  MaskStream stream(objectOnFrameZero(person), options);
  for (std::uint64_t frame = 0; frame < 10; ++frame) {
    const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
    cv::Mat depth(48, 64, CV_32FC1, cv::Scalar(3.0f));
    depth(person) = 0.40f - 0.015f * static_cast<float>(frame);
    const cv::Mat dynamic = stream.masksFor(frame, bgr, depth).dynamic;
    EXPECT_EQ(cv::countNonZero(dynamic & ~cv::Mat(depth < 1.0f)), 0) << frame;
    EXPECT_EQ(cv::countNonZero(cv::Mat(depth < 1.0f) & ~dynamic), 0) << frame;
  }
}

TEST(MaskStream, BusyTrackingGetsTheSegmenterOnlyEveryBusyIntervalFrames) {
  MaskStreamOptions options;
  options.busy_interval = 10;
  MaskStream stream(countingSegment(), options);
  stream.setTrackingBusyShare(1.0);  // tracking never waits for a frame
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  for (std::uint64_t frame = 0; frame < 60; ++frame) {
    ASSERT_EQ(stream.masksFor(frame, bgr, cv::Mat()).dynamic.size(), bgr.size()) << frame;
  }
  // Frames 0, 10, ..., 50 at most; a frame is skipped when the segmenter is still busy.
  EXPECT_GE(stream.runs(), 1);
  EXPECT_LE(stream.runs(), 6);
}

TEST(MaskStream, TrackingThatWaitsForItsFramesGetsTheSegmenterWheneverItIsFree) {
  MaskStream stream(countingSegment());
  stream.setTrackingBusyShare(0.3);  // 10 ms of work per 33 ms frame
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  constexpr int kFrames = 40;
  for (std::uint64_t frame = 0; frame < kFrames; ++frame) {
    ASSERT_EQ(stream.masksFor(frame, bgr, cv::Mat()).dynamic.size(), bgr.size()) << frame;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // Throttled it would run once (every 45 frames); a frame is skipped only when the
  // segmenter thread has not finished the one before, which a loaded machine may cause.
  EXPECT_GE(stream.runs(), kFrames / 2);
}

TEST(MaskStream, AsynchronousSegmenterSeesFramesInOrder) {
  auto record = std::make_shared<RecordedJobs>();
  MaskStream stream(recordingSegment(record));
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 80, 120));
  for (std::uint64_t frame = 1; frame <= 20; ++frame) {
    EXPECT_EQ(stream.masksFor(frame, bgr, cv::Mat()).dynamic.size(), bgr.size());
  }
  std::lock_guard lock(record->mutex);
  ASSERT_FALSE(record->previous_and_current.empty());
  EXPECT_EQ(record->previous_and_current.front().second, 1u);  // the first frame waits
  for (std::size_t i = 1; i < record->previous_and_current.size(); ++i) {
    const auto [previous, current] = record->previous_and_current[i];
    EXPECT_GT(current, record->previous_and_current[i - 1].second);
    EXPECT_EQ(previous + 1, current);
  }
}

}  // namespace
}  // namespace segslam::segmentation
