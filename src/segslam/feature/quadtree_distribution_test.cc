#include "segslam/feature/quadtree_distribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <opencv2/core.hpp>

namespace segslam::feature {
namespace {

cv::KeyPoint candidate(float x, float y, float response) {
  return cv::KeyPoint(cv::Point2f(x, y), 7.0f, -1.0f, response);
}

TEST(QuadtreeDistribution, SpreadsOverTheAreaInsteadOfTakingTheStrongest) {
  // A dense, strong cluster in the top-left corner and a sparse, weak grid elsewhere.
  std::vector<cv::KeyPoint> candidates;
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 20; ++x) candidates.push_back(candidate(x + 0.5f, y + 0.5f, 100.0f + x));
  }
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) candidates.push_back(candidate(x * 40 + 20, y * 40 + 20, 10.0f));
  }
  const auto kept = distributeWithQuadtree(candidates, cv::Rect2f(0, 0, 320, 320), 64);
  ASSERT_EQ(kept.size(), 64u);
  // Every 80 x 80 block of a 4 x 4 grid is represented.
  std::array<int, 16> per_block{};
  for (const auto& keypoint : kept) {
    ++per_block[static_cast<int>(keypoint.pt.y / 80) * 4 + static_cast<int>(keypoint.pt.x / 80)];
  }
  for (std::size_t block = 0; block < per_block.size(); ++block) {
    EXPECT_GE(per_block[block], 2) << "block " << block;
  }
}

TEST(QuadtreeDistribution, KeepsTheStrongestOfEachNode) {
  // Two candidates per quadrant of the area; asking for 4 keeps the stronger of each pair.
  std::vector<cv::KeyPoint> candidates;
  const std::array<cv::Point2f, 4> centres = {cv::Point2f(10, 10), cv::Point2f(90, 10),
                                              cv::Point2f(10, 90), cv::Point2f(90, 90)};
  for (std::size_t q = 0; q < centres.size(); ++q) {
    candidates.push_back(candidate(centres[q].x, centres[q].y, 1.0f));
    candidates.push_back(candidate(centres[q].x + 1, centres[q].y, 2.0f + q));
  }
  const auto kept = distributeWithQuadtree(candidates, cv::Rect2f(0, 0, 100, 100), 4);
  ASSERT_EQ(kept.size(), 4u);
  for (const auto& keypoint : kept) EXPECT_GE(keypoint.response, 2.0f);
}

TEST(QuadtreeDistribution, ReturnsExactlyTheBudgetOrAllCandidates) {
  cv::RNG rng(7);
  std::vector<cv::KeyPoint> candidates;
  for (int i = 0; i < 500; ++i) {
    candidates.push_back(
        candidate(rng.uniform(0.0f, 640.0f), rng.uniform(0.0f, 480.0f), rng.uniform(0.0f, 50.0f)));
  }
  const cv::Rect2f area(0, 0, 640, 480);
  for (const int count : {0, 1, 3, 37, 100, 499, 500, 800}) {
    const auto kept = distributeWithQuadtree(candidates, area, count);
    EXPECT_EQ(static_cast<int>(kept.size()), std::min(count, 500)) << "count " << count;
  }
  EXPECT_TRUE(distributeWithQuadtree({}, area, 10).empty());
}

TEST(QuadtreeDistribution, CopesWithDuplicatePositionsAndIsDeterministic) {
  std::vector<cv::KeyPoint> candidates(5, candidate(3, 3, 1.0f));
  candidates.push_back(candidate(50, 50, 1.0f));
  const auto kept = distributeWithQuadtree(candidates, cv::Rect2f(0, 0, 64, 64), 4);
  EXPECT_EQ(kept.size(), 2u);  // the five duplicates can only ever be one node
  EXPECT_EQ(kept[0].pt, cv::Point2f(3, 3));
  const auto again = distributeWithQuadtree(candidates, cv::Rect2f(0, 0, 64, 64), 4);
  ASSERT_EQ(again.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(again[i].pt, kept[i].pt);
}

}  // namespace
}  // namespace segslam::feature
