#include "segslam/loop/bow_loop_detector.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "segslam/feature/orb_extractor.h"
#include "segslam/loop/loop_test_scenes.h"
#include "segslam/synth/sequence.h"

namespace segslam::loop {
namespace {

using Entry = BowLoopDetector::Entry;

std::shared_ptr<const place::Vocabulary> shippedVocabulary() {
  static const auto vocabulary = std::make_shared<const place::Vocabulary>(place::Vocabulary::load(
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config" / place::kDefaultVocabularyFile));
  return vocabulary;
}

TEST(BowLoopDetector, EntryHasTheWordsOfTheStaticKeypointsOnly) {
  const auto vocabulary = shippedVocabulary();
  const BowLoopDetector detector(vocabulary);
  // A person covers the left half (x < 150); keypoints on both halves, one row of them each.
  cv::Mat dynamic_mask = cv::Mat::zeros(480, 640, CV_8U);
  dynamic_mask.colRange(0, 150).setTo(255);
  cv::Mat descriptors(200, 32, CV_8U);
  cv::randu(descriptors, 0, 256);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat static_descriptors;
  for (int k = 0; k < descriptors.rows; ++k) {
    keypoints.emplace_back(static_cast<float>(k % 20) * 15.0F, static_cast<float>(k / 20) * 30.0F,
                           31.0F);
    if (keypoints.back().pt.x >= 150.0F) static_descriptors.push_back(descriptors.row(k));
  }
  const auto camera = std::make_shared<map::FrameCamera>(
      core::Camera{}, map::kDefaultVirtualBaselineM, 40.0, feature::ScaleLevels(8, 1.2));
  const map::Frame frame(0, 0.0, keypoints, descriptors, cv::Mat(), dynamic_mask, camera);
  const map::KeyFrame keyframe(0, frame);
  const Entry entry = detector.entryOf(keyframe);
  EXPECT_EQ(entry.keyframe, &keyframe);
  const place::BowVector expected = vocabulary->transform(static_descriptors);
  ASSERT_EQ(entry.bow.size(), expected.size());
  for (const auto& [word, weight] : expected) EXPECT_NEAR(entry.bow.at(word), weight, 1e-9);
}

// Keyframes every 20 frames of a synthetic lap round a room (640 frames: 11.25 degrees apart),
// each covisible with its two predecessors, as the tracker would link them.
class BowLoopDetectorOnALap : public ::testing::Test {
 protected:
  static constexpr int kStep = 20;

  BowLoopDetectorOnALap() : sequence_(roomLapOptions()) {}

  map::KeyFrame& addKeyFrame(int frame) {
    const synth::FrameImages images = sequence_.renderFrame(frame);
    cv::Mat gray;
    cv::cvtColor(images.rgb, gray, cv::COLOR_BGR2GRAY);
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
    extractor_.extract(gray, cv::Mat(), keypoints, descriptors);
    const map::Frame image(static_cast<std::uint64_t>(frame), sequence_.timestamp(frame),
                           std::move(keypoints), descriptors, cv::Mat(), cv::Mat(), camera_);
    auto keyframe = std::make_unique<map::KeyFrame>(keyframes_.size(), image);
    for (std::size_t back = 1; back <= 2 && back <= keyframes_.size(); ++back) {
      map::KeyFrame& previous = *keyframes_[keyframes_.size() - back];
      keyframe->addConnection(&previous, 100);
      previous.addConnection(keyframe.get(), 100);
    }
    keyframes_.push_back(std::move(keyframe));
    return *keyframes_.back();
  }

  // The query's candidates after every keyframe before it was added.
  std::vector<std::uint64_t> candidatesOf(const map::KeyFrame& query,
                                          BowLoopDetector& detector) const {
    for (const auto& keyframe : keyframes_) {
      if (keyframe.get() != &query) detector.add(*keyframe);
    }
    std::set<std::uint64_t> covisible = {query.id};
    for (const map::KeyFrame* k : query.covisiblesWithWeight(0)) covisible.insert(k->id);
    return detector.candidates(query, covisible, 3);
  }

  synth::SyntheticSequence sequence_;
  feature::OrbExtractor extractor_;
  std::shared_ptr<const map::FrameCamera> camera_ = std::make_shared<map::FrameCamera>(
      sequence_.camera(), map::kDefaultVirtualBaselineM, 40.0, feature::ScaleLevels(8, 1.2));
  std::vector<std::unique_ptr<map::KeyFrame>> keyframes_;
};

TEST_F(BowLoopDetectorOnALap, RevisitedStartIsACandidate) {
  for (int frame = 0; frame <= 600; frame += kStep) addKeyFrame(frame);
  // 10 frames before the end: between the last keyframe and the first, seen 11 degrees apart.
  const map::KeyFrame& query = addKeyFrame(630);
  BowLoopDetector detector(shippedVocabulary());
  const auto found = candidatesOf(query, detector);
  ASSERT_FALSE(found.empty());
  EXPECT_LE(found.front(), 1U);  // the lap's first keyframes
}

TEST_F(BowLoopDetectorOnALap, PlaceSeenForTheFirstTimeHasNoCandidate) {
  for (int frame = 0; frame <= 300; frame += kStep) addKeyFrame(frame);
  const map::KeyFrame& query = addKeyFrame(320);  // half way round: new walls
  BowLoopDetector detector(shippedVocabulary());
  EXPECT_TRUE(candidatesOf(query, detector).empty());
}

}  // namespace
}  // namespace segslam::loop
