#include "segslam/loop/descriptor_vote_detector.h"

#include <gtest/gtest.h>

#include <random>

namespace segslam::loop {
namespace {

using Signature = DescriptorVoteDetector::Signature;

Signature randomSignature(std::uint64_t id, std::uint32_t seed, int size = 200) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_real_distribution<float> position(0.0f, 300.0f);
  Signature signature;
  signature.keyframe_id = id;
  signature.descriptors.create(size, 32, CV_8U);
  for (int r = 0; r < size; ++r) {
    for (int b = 0; b < 32; ++b)
      signature.descriptors.at<std::uint8_t>(r, b) = static_cast<std::uint8_t>(byte(rng));
    signature.pixels.emplace_back(position(rng), position(rng));
  }
  return signature;
}

TEST(DescriptorVoteDetector, SamePlaceScoresHighUnrelatedPlaceLow) {
  const DescriptorVoteDetector detector;
  const Signature a = randomSignature(1, 1);
  Signature same_place = a;
  same_place.keyframe_id = 2;
  same_place.descriptors = a.descriptors.clone();
  for (int r = 0; r < 100; ++r) same_place.descriptors.at<std::uint8_t>(r, 0) ^= 0x0F;  // 4 bits
  EXPECT_GT(detector.score(a, same_place), 0.9);
  EXPECT_LT(detector.score(a, randomSignature(3, 2)), 0.02);
}

TEST(DescriptorVoteDetector, KeypointsOnTheOthersDynamicAreaDoNotVote) {
  const DescriptorVoteDetector detector;
  const Signature a = randomSignature(1, 1);
  Signature b = a;
  b.keyframe_id = 2;
  // Everything left of column 150 moves in b: only a's keypoints right of it may vote.
  cv::Mat left_moves = cv::Mat::zeros(300, 300, CV_8U);
  left_moves.colRange(0, 150).setTo(255);
  b.dynamic_mask = feature::RunLengthMask(left_moves);
  EXPECT_DOUBLE_EQ(detector.score(a, b), 1.0);
  Signature unrelated_right = randomSignature(3, 4);
  unrelated_right.dynamic_mask = b.dynamic_mask;
  EXPECT_LT(detector.score(a, unrelated_right), 0.05);
}

}  // namespace
}  // namespace segslam::loop
