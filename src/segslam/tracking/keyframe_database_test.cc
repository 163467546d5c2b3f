#include "segslam/tracking/keyframe_database.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

namespace segslam::tracking {
namespace {

std::shared_ptr<const place::Vocabulary> shippedVocabulary() {
  static const auto vocabulary = std::make_shared<const place::Vocabulary>(place::Vocabulary::load(
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config" / place::kDefaultVocabularyFile));
  return vocabulary;
}

// A frame whose 300 keypoints carry random descriptors drawn from `seed`: frames of different
// seeds share only the words that chance gives them.
map::Frame randomFrame(std::uint64_t id, int seed) {
  cv::RNG rng(seed);
  cv::Mat descriptors(300, 32, CV_8U);
  rng.fill(descriptors, cv::RNG::UNIFORM, 0, 256);
  std::vector<cv::KeyPoint> keypoints;
  for (int k = 0; k < descriptors.rows; ++k) {
    keypoints.emplace_back(static_cast<float>(k % 20) * 30.0F, static_cast<float>(k / 20) * 30.0F,
                           31.0F);
  }
  static const auto camera = std::make_shared<map::FrameCamera>(
      core::Camera{}, map::kDefaultVirtualBaselineM, 40.0, feature::ScaleLevels(8, 1.2));
  return {id, 0.0, keypoints, descriptors, cv::Mat(), cv::Mat(), camera};
}

std::vector<std::shared_ptr<map::KeyFrame>> fiveKeyFrames(KeyFrameDatabase& database) {
  std::vector<std::shared_ptr<map::KeyFrame>> keyframes;
  for (int k = 0; k < 5; ++k) {
    keyframes.push_back(std::make_shared<map::KeyFrame>(k, randomFrame(k, k)));
    database.add(keyframes.back());
  }
  return keyframes;
}

TEST(KeyFrameDatabase, TheKeyFrameThatShowsWhatTheFrameShowsComesFirst) {
  KeyFrameDatabase database(shippedVocabulary());
  const auto keyframes = fiveKeyFrames(database);
  map::Frame frame = randomFrame(10, 3);
  // A third of the descriptors changed: the frame sees keyframe 3's place, not exactly its view.
  cv::RNG rng(99);
  rng.fill(frame.descriptors.rowRange(0, 100), cv::RNG::UNIFORM, 0, 256);
  const auto candidates = database.candidates(frame, 3);
  ASSERT_FALSE(candidates.empty());
  EXPECT_EQ(candidates.front(), keyframes[3]);
  EXPECT_LE(candidates.size(), 3U);
  EXPECT_EQ(database.size(), 5U);
}

TEST(KeyFrameDatabase, CulledKeyFramesAreNoCandidates) {
  KeyFrameDatabase database(shippedVocabulary());
  const auto keyframes = fiveKeyFrames(database);
  keyframes[3]->setBad();
  for (const auto& candidate : database.candidates(randomFrame(10, 3), 5)) {
    EXPECT_NE(candidate, keyframes[3]);
  }
}

TEST(KeyFrameDatabase, CulledKeyFramesAreForgottenAtTheNextAdd) {
  KeyFrameDatabase database(shippedVocabulary());
  const auto keyframes = fiveKeyFrames(database);
  keyframes[1]->setBad();
  keyframes[3]->setBad();
  database.add(std::make_shared<map::KeyFrame>(5, randomFrame(5, 5)));
  EXPECT_EQ(database.size(), 4U);
  // Nothing of the culled keyframe's place is left to match, not even its features.
  keyframes[3]->releaseFeatures();
  for (const auto& candidate : database.candidates(randomFrame(10, 3), 5)) {
    EXPECT_NE(candidate, keyframes[3]);
  }
}

TEST(KeyFrameDatabase, NeedsAVocabulary) {
  EXPECT_THROW(KeyFrameDatabase(nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::tracking
