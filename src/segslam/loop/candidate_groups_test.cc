#include "segslam/loop/candidate_groups.h"

#include <gtest/gtest.h>

namespace segslam::loop {
namespace {

class CandidateGroupsTest : public ::testing::Test {
 protected:
  CandidateGroupsTest() {
    for (std::uint64_t id = 0; id < 6; ++id) {
      keyframes_.push_back(std::make_unique<map::KeyFrame>(id, map::Frame()));
    }
  }

  void connect(std::uint64_t a, std::uint64_t b) {
    keyframes_[a]->addConnection(keyframes_[b].get(), 50);
    keyframes_[b]->addConnection(keyframes_[a].get(), 50);
  }

  std::vector<std::uint64_t> groups(const std::unordered_map<std::uint64_t, double>& scores,
                                    std::size_t max_candidates = 3) const {
    return bestCandidateGroups(
        scores, [&](std::uint64_t id) { return keyframes_[id].get(); }, {}, max_candidates);
  }

  std::vector<std::unique_ptr<map::KeyFrame>> keyframes_;
};

TEST_F(CandidateGroupsTest, ThresholdIsTheWeakestOrMeanKnownCovisibleScoreAtLeastTheMinimum) {
  const std::unordered_map<std::uint64_t, double> known = {{1, 0.6}, {2, 0.4}};
  const auto score_of = [&](std::uint64_t id) -> std::optional<double> {
    const auto it = known.find(id);
    return it == known.end() ? std::nullopt : std::optional<double>(it->second);
  };
  const map::KeyFrame& query = *keyframes_[0];
  EXPECT_DOUBLE_EQ(covisibleScoreThreshold(query, {0, 1, 2, 3}, score_of, 0.1), 0.4);
  EXPECT_DOUBLE_EQ(covisibleScoreThreshold(query, {0, 1, 2}, score_of, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(covisibleScoreThreshold(query, {0, 3}, score_of, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(
      covisibleScoreThreshold(query, {0, 1, 2, 3}, score_of, 0.1, CovisibleScore::kMean), 0.5);
}

TEST_F(CandidateGroupsTest, PlaceSeenBySeveralKeyFramesBeatsASingleLookAlike) {
  connect(1, 2);
  connect(2, 3);
  // 1-2-3 see the same place; 5 alone scores highest.
  const auto found = groups({{1, 0.5}, {2, 0.6}, {3, 0.5}, {5, 0.8}});
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found.front(), 2U);  // the group's best keyframe
  EXPECT_EQ(std::count(found.begin(), found.end(), 5U), 0);
}

TEST_F(CandidateGroupsTest, NoScoresNoCandidatesAndAtMostTheMaximum) {
  EXPECT_TRUE(groups({}).empty());
  EXPECT_EQ(groups({{1, 0.5}, {3, 0.5}, {5, 0.5}}, 2).size(), 2U);
}

}  // namespace
}  // namespace segslam::loop
