#include "segslam/eval/rpe.h"

#include <gtest/gtest.h>

#include <cmath>

#include "segslam/eval/test_trajectories.h"
#include "segslam/util/error.h"

namespace segslam::eval {
namespace {

using fixtures::alongX;

std::vector<double> translationalErrors(const RpeResult& result) {
  std::vector<double> errors;
  for (const auto& pair : result.pairs) errors.push_back(pair.translational_error);
  return errors;
}

// Ground truth moves 1 m per second along x; the estimate overshoots the step from 1 s to 2 s.
const core::Trajectory kGroundTruth = alongX({0, 1, 2, 3, 4}, {0, 1, 2, 3, 4});
const core::Trajectory kEstimate = alongX({0, 1, 2, 3, 4}, {0, 1, 2.5, 3.5, 4.5});

TEST(Rpe, HandComputedOneFramePairs) {
  const auto result = evaluateRpe(kGroundTruth, kEstimate, {.delta_unit = DeltaUnit::kFrames});
  // Pairs (0,1), (1,2), (2,3); (3,4) ends at the last pose and is dropped like the tool does.
  ASSERT_EQ(result.pairs.size(), 3u);
  EXPECT_EQ(result.pairs[2].first_index, 2u);
  EXPECT_EQ(result.pairs[2].second_index, 3u);
  const auto errors = translationalErrors(result);
  EXPECT_NEAR(errors[0], 0.0, 1e-12);
  EXPECT_NEAR(errors[1], 0.5, 1e-12);
  EXPECT_NEAR(errors[2], 0.0, 1e-12);
  EXPECT_NEAR(result.translational.rmse, std::sqrt(0.25 / 3.0), 1e-12);
  EXPECT_NEAR(result.rotational_deg.max, 0.0, 1e-9);
}

TEST(Rpe, DeltaInSecondsUsesTimestamps) {
  // Poses every 0.5 s: a 1 s delta spans two poses.
  const auto stamps = fixtures::stampsFrom(0.0, 0.5, 5);
  const auto gt = alongX(stamps, {0, 1, 2, 3, 4});
  const auto est = alongX(stamps, {0, 1, 2, 3.5, 4.5});
  const auto result = evaluateRpe(gt, est, {.delta = 1.0, .delta_unit = DeltaUnit::kSeconds});
  // (0,2), (1,3); (2,4) ends at the last pose.
  ASSERT_EQ(result.pairs.size(), 2u);
  EXPECT_EQ(result.pairs[1].second_index, 3u);
  EXPECT_NEAR(translationalErrors(result)[0], 0.0, 1e-12);
  EXPECT_NEAR(translationalErrors(result)[1], 0.5, 1e-12);
}

TEST(Rpe, RotationErrorInDegrees) {
  core::Trajectory gt;
  core::Trajectory est;
  for (int k = 0; k < 4; ++k) {
    gt.append(k, fixtures::poseAt({0, 0, 0}, 0.0));
    est.append(k, fixtures::poseAt({0, 0, 0}, 10.0 * k));
  }
  const auto result = evaluateRpe(gt, est, {.delta_unit = DeltaUnit::kFrames});
  ASSERT_EQ(result.pairs.size(), 2u);
  EXPECT_NEAR(result.rotational_deg.mean, 10.0, 1e-6);
  EXPECT_NEAR(result.translational.max, 0.0, 1e-12);
}

TEST(Rpe, ScaleMultipliesTheEstimatedMotion) {
  const auto half = alongX({0, 1, 2, 3, 4}, {0, 0.5, 1, 1.5, 2});
  EXPECT_NEAR(evaluateRpe(kGroundTruth, half).translational.rmse, 0.5, 1e-12);
  EXPECT_NEAR(evaluateRpe(kGroundTruth, half, {.scale = 2.0}).translational.rmse, 0.0, 1e-12);
}

TEST(Rpe, OffsetShiftsTheEstimateClock) {
  const auto shifted = alongX({100, 101, 102, 103, 104}, {0, 1, 2.5, 3.5, 4.5});
  const auto result =
      evaluateRpe(kGroundTruth, shifted, {.delta_unit = DeltaUnit::kFrames, .offset = -100.0});
  EXPECT_NEAR(result.translational.rmse, std::sqrt(0.25 / 3.0), 1e-12);
  EXPECT_DOUBLE_EQ(result.pairs[0].gt_stamp_0, 0.0);
  EXPECT_DOUBLE_EQ(result.pairs[0].est_stamp_0, 100.0);
}

TEST(Rpe, PairsWithoutCloseGroundTruthAreSkipped) {
  // Ground truth every second up to 9 s (so at most 2 s away); estimate poses at 15 s and later
  // find their closest ground truth at 9 s, too far away.
  const auto gt = alongX(fixtures::stampsFrom(0.0, 1.0, 10), {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  const auto est = alongX({0, 1, 2, 15, 16, 17}, {0, 1, 2, 15, 16, 17});
  const auto result = evaluateRpe(gt, est, {.delta_unit = DeltaUnit::kFrames});
  ASSERT_EQ(result.pairs.size(), 2u);
  EXPECT_EQ(result.pairs[1].second_index, 2u);
}

TEST(Rpe, AnyPairsComparesEveryPairOfFewPoses) {
  const auto result = evaluateRpe(kGroundTruth, kEstimate, {.fixed_delta = false});
  EXPECT_EQ(result.pairs.size(), 25u);
}

TEST(Rpe, SampledPairsAreRepeatableForASeed) {
  const auto gt = fixtures::wigglyPath(200);
  const auto est = fixtures::transformed(gt, fixtures::poseAt({0.01, 0, 0}, 1.0));
  const RpeOptions options{.delta_unit = DeltaUnit::kFrames, .max_pairs = 20, .seed = 5};
  const auto first = evaluateRpe(gt, est, options);
  EXPECT_EQ(first.pairs.size(), 20u);
  const auto second = evaluateRpe(gt, est, options);
  for (std::size_t k = 0; k < first.pairs.size(); ++k) {
    EXPECT_EQ(first.pairs[k].first_index, second.pairs[k].first_index);
  }
}

TEST(Rpe, TimestampsThatDoNotOverlapAreAnError) {
  const auto far = alongX({100, 101, 102}, {0, 1, 2});
  EXPECT_THROW(evaluateRpe(kGroundTruth, far), util::Error);
}

TEST(Rpe, TooFewPairsIsAnError) {
  // Two poses: the only pair (0, 1) ends at the last pose.
  const auto two = alongX({0, 1}, {0, 1});
  EXPECT_THROW(evaluateRpe(kGroundTruth, two, {.delta_unit = DeltaUnit::kFrames}), util::Error);
}

TEST(Rpe, AnEstimateShorterThanTheDeltaSaysSo) {
  // 0.5 s of poses against 2 s of ground truth: no pair is 1 s apart.
  const auto gt = alongX(fixtures::stampsFrom(0.0, 0.1, 20), std::vector<double>(20, 0.0));
  const auto short_estimate =
      alongX(fixtures::stampsFrom(0.0, 0.1, 6), std::vector<double>(6, 0.0));
  try {
    evaluateRpe(gt, short_estimate);
    FAIL() << "expected an error";
  } catch (const util::Error& e) {
    EXPECT_STREQ(e.what(),
                 "the estimate spans 0.500 s (6 poses) and has 0 pose pair(s) 1 s apart (pairs "
                 "ending at its last pose do not count, as in the TUM tool); need at least 2");
  }
}

}  // namespace
}  // namespace segslam::eval
