#include "segslam/eval/ate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "segslam/eval/test_trajectories.h"
#include "segslam/io/timestamp_association.h"
#include "segslam/util/error.h"

namespace segslam::eval {
namespace {

using fixtures::alongX;

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

std::vector<std::pair<double, double>> matchedStamps(const AteResult& result) {
  std::vector<std::pair<double, double>> stamps;
  for (const auto& pair : result.pairs) stamps.emplace_back(pair.gt_stamp, pair.est_stamp);
  return stamps;
}

TEST(AteAssociation, EqualDifferencesGoToTheSmallerFirstThenSecondStamp) {
  // 1.0 and 2.0 are both 0.5 from 1.5: the smaller first stamp wins.
  EXPECT_EQ(io::associateTimestamps({1.0, 2.0}, {1.5}, 0.6), (Pairs{{0, 0}}));
  // 1.0 and 2.0 are both 0.5 from 1.5: the smaller second stamp wins.
  EXPECT_EQ(io::associateTimestamps({1.5}, {1.0, 2.0}, 0.6), (Pairs{{0, 0}}));
}

TEST(AteAssociation, GreedyByDifferenceAndEachStampOnce) {
  // 1.1 is closer to 1.08 than 1.0 is, so 1.0 stays unmatched though within range.
  EXPECT_EQ(io::associateTimestamps({1.0, 1.1}, {1.08}, 0.1), (Pairs{{1, 0}}));
  // The limit is strict: a difference of exactly max_difference does not match.
  EXPECT_TRUE(io::associateTimestamps({1.0}, {1.5}, 0.5).empty());
}

TEST(AteAssociation, OffsetIsAddedToTheSecondStamps) {
  EXPECT_TRUE(io::associateTimestamps({10.0, 11.0}, {0.0, 1.0}, 0.02).empty());
  EXPECT_EQ(io::associateTimestamps({10.0, 11.0}, {0.0, 1.0}, 0.02, 10.0), (Pairs{{0, 0}, {1, 1}}));
  // The offset decides which of two candidates is closer to 11.0.
  EXPECT_EQ(io::associateTimestamps({10.0, 11.0}, {0.99, 1.015}, 0.02, 10.0), (Pairs{{1, 0}}));
  EXPECT_EQ(io::associateTimestamps({10.0, 11.0}, {0.99, 1.015}, 0.02, 9.99), (Pairs{{1, 1}}));
}

TEST(AteAssociation, EvaluateAteMatchesLikeTheTool) {
  const auto gt = alongX({1.0, 2.0, 3.0, 4.0}, {0.0, 1.0, 2.0, 3.0});
  const auto est = alongX({0.995, 2.01, 2.5, 4.03}, {0.0, 1.0, 5.0, 3.0});
  const auto result = evaluateAte(gt, est, {.max_difference = 0.02});
  EXPECT_EQ(matchedStamps(result),
            (std::vector<std::pair<double, double>>{{1.0, 0.995}, {2.0, 2.01}}));
}

TEST(Ate, Se3AlignedCopyOfTheGroundTruthHasNoError) {
  const auto gt = fixtures::wigglyPath(60);
  const auto est = fixtures::transformed(gt, fixtures::poseAt({3.0, -1.0, 0.5}, 40.0));
  const auto result = evaluateAte(gt, est);
  EXPECT_EQ(result.pairs.size(), 60u);
  EXPECT_LT(result.statistics.max, 1e-9);
  // The aligned estimate lies on the ground truth, orientation included.
  for (std::size_t k = 0; k < gt.size(); ++k) {
    EXPECT_TRUE(result.aligned_estimate[k].T_wc.isApprox(gt[k].T_wc, 1e-9));
  }
}

TEST(Ate, TrajectoryAgainstItselfHasNoError) {
  const auto gt = fixtures::wigglyPath(30);
  const auto result = evaluateAte(gt, gt);
  EXPECT_LT(result.statistics.rmse, 1e-12);
  EXPECT_TRUE(result.alignment.matrix().isApprox(Eigen::Matrix4d::Identity(), 1e-12));
}

TEST(Ate, WithoutAlignmentAShiftIsTheError) {
  const auto gt = alongX({0.0, 1.0, 2.0}, {0.0, 1.0, 2.0});
  const auto est = alongX({0.0, 1.0, 2.0}, {0.5, 1.5, 2.5});
  const auto result = evaluateAte(gt, est, {.alignment = AlignmentMethod::kNone});
  EXPECT_DOUBLE_EQ(result.statistics.rmse, 0.5);
  EXPECT_DOUBLE_EQ(result.statistics.min, 0.5);
  EXPECT_LT(evaluateAte(gt, est).statistics.rmse, 1e-12);
}

TEST(Ate, ScaleIsFoundBySim3OrGivenByTheUser) {
  const auto gt = fixtures::wigglyPath(40);
  core::Trajectory half;
  for (const auto& pose : gt.poses()) {
    geometry::Pose scaled = pose.T_wc;
    scaled.translation() *= 0.5;
    half.append(pose.timestamp, scaled);
  }
  const auto sim3 = evaluateAte(gt, half, {.alignment = AlignmentMethod::kSim3});
  EXPECT_NEAR(sim3.alignment.scale, 2.0, 1e-9);
  EXPECT_LT(sim3.statistics.max, 1e-9);
  EXPECT_GT(evaluateAte(gt, half).statistics.rmse, 0.05);
  EXPECT_LT(evaluateAte(gt, half, {.scale = 2.0}).statistics.max, 1e-9);
}

TEST(Ate, StatisticsCoverTheMatchedPoses) {
  // Unaligned: errors 0, 1, 0, 3 against a ground truth at the origin.
  const auto gt = alongX({0.0, 1.0, 2.0, 3.0}, {0.0, 0.0, 0.0, 0.0});
  const auto est = alongX({0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 3.0});
  const auto stats = evaluateAte(gt, est, {.alignment = AlignmentMethod::kNone}).statistics;
  EXPECT_EQ(stats.count, 4u);
  EXPECT_DOUBLE_EQ(stats.rmse, std::sqrt(10.0 / 4.0));
  EXPECT_DOUBLE_EQ(stats.mean, 1.0);
  EXPECT_DOUBLE_EQ(stats.median, 0.5);
  EXPECT_DOUBLE_EQ(stats.max, 3.0);
}

TEST(Ate, GroundTruthInEstimateFrameOverlaysTheEstimate) {
  const auto gt = fixtures::wigglyPath(30);
  geometry::Pose offset = fixtures::poseAt({0.4, -1.0, 2.0}, 35.0);
  const auto est = fixtures::transformed(gt, offset);
  const AteOptions options{.scale = 0.5, .alignment = AlignmentMethod::kSim3};
  const auto moved = groundTruthInEstimateFrame(gt, evaluateAte(gt, est, options), options);
  ASSERT_EQ(moved.size(), est.size());
  for (std::size_t k = 0; k < est.size(); ++k) {
    EXPECT_TRUE(moved[k].T_wc.isApprox(est[k].T_wc, 1e-9)) << "pose " << k;
  }
}

TEST(Ate, FewerThanTwoMatchesIsAnError) {
  const auto gt = alongX({0.0, 1.0}, {0.0, 1.0});
  const auto est = alongX({1.0, 5.0}, {0.0, 1.0});
  EXPECT_THROW(evaluateAte(gt, est), util::Error);
}

}  // namespace
}  // namespace segslam::eval
