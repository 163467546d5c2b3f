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

// Words with a non-zero weight, one per keypoint, so that every keypoint counts.
std::vector<place::WordId> weightedWords(const place::Vocabulary& vocabulary, std::size_t count,
                                         place::WordId first) {
  std::vector<place::WordId> words;
  for (place::WordId w = first; words.size() < count; ++w) {
    if (vocabulary.idf(w) > 0.0F) words.push_back(w);
  }
  return words;
}

// The entry's bag of words over all its keypoints, weighted as the detector weighs them.
void fillBow(Entry& entry, const place::Vocabulary& vocabulary) {
  entry.bow.clear();
  for (const place::WordId word : entry.words) entry.bow[word] += vocabulary.idf(word);
  place::normaliseL1(entry.bow);
}

TEST(BowLoopDetector, UnionMaskDropsKeypointsOnEitherDynamicArea) {
  const auto vocabulary = shippedVocabulary();
  const BowLoopDetector detector(vocabulary);
  // The same wall seen twice; in b a person covers the left half (x < 150), where a's keypoints
  // have no counterpart.
  const auto words = weightedWords(*vocabulary, 200, 0);
  Entry a;
  Entry b;
  b.dynamic_mask = cv::Mat::zeros(300, 300, CV_8U);
  b.dynamic_mask.colRange(0, 150).setTo(255);
  for (std::size_t k = 0; k < words.size(); ++k) {
    const cv::Point2f pixel(static_cast<float>(k % 20) * 15.0F, static_cast<float>(k / 20) * 30.0F);
    a.words.push_back(words[k]);
    a.pixels.push_back(pixel);
    if (pixel.x >= 150.0F) {
      b.words.push_back(words[k]);
      b.pixels.push_back(pixel);
    }
  }
  fillBow(a, *vocabulary);
  fillBow(b, *vocabulary);
  const auto kept = BowLoopDetector::keypointsStaticIn(a, b);
  EXPECT_EQ(kept.size(), b.words.size());
  for (const std::size_t k : kept) EXPECT_GE(a.pixels[k].x, 150.0F);
  EXPECT_EQ(BowLoopDetector::keypointsStaticIn(b, a).size(), b.words.size());
  EXPECT_DOUBLE_EQ(detector.unionMaskScore(a, b), 1.0);
  // Without b's mask, a's keypoints behind the person count against the match.
  b.dynamic_mask = cv::Mat();
  EXPECT_NEAR(detector.unionMaskScore(a, b), 0.5, 0.05);
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
      sequence_.camera(), 40.0, 40.0, feature::ScaleLevels(8, 1.2));
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
