#include "segslam/eval/precision_recall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace segslam::eval {
namespace {

TEST(PrecisionRecall, PerfectScorerHasAveragePrecisionOne) {
  const std::vector<ScoredPair> pairs = {{0.9, true}, {0.8, true}, {0.3, false}, {0.1, false}};
  const PrCurve curve = precisionRecall(pairs);
  EXPECT_DOUBLE_EQ(curve.average_precision, 1.0);
  EXPECT_EQ(curve.positives, 2u);
  EXPECT_EQ(curve.negatives, 2u);
  ASSERT_EQ(curve.points.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.points[1].recall, 1.0);
  EXPECT_DOUBLE_EQ(curve.points[1].precision, 1.0);
  EXPECT_DOUBLE_EQ(curve.points[3].precision, 0.5);
}

TEST(PrecisionRecall, HandMadeRanking) {
  // Ranking: +, -, +, -: precision 1 at recall 0.5, 2/3 at recall 1.
  const std::vector<ScoredPair> pairs = {{4, true}, {3, false}, {2, true}, {1, false}};
  const PrCurve curve = precisionRecall(pairs);
  EXPECT_NEAR(curve.average_precision, 0.5 * 1.0 + 0.5 * 2.0 / 3.0, 1e-12);
}

TEST(PrecisionRecall, TiedScoresAreOneThreshold) {
  const std::vector<ScoredPair> pairs = {{1, true}, {1, false}, {0, false}};
  const PrCurve curve = precisionRecall(pairs);
  ASSERT_EQ(curve.points.size(), 2u);
  EXPECT_DOUBLE_EQ(curve.points[0].precision, 0.5);
  EXPECT_DOUBLE_EQ(curve.average_precision, 0.5);
}

TEST(PrecisionRecall, RandomScorerAveragePrecisionIsAboutThePositiveRate) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<ScoredPair> pairs;
  for (int k = 0; k < 20000; ++k) pairs.push_back({uniform(random), uniform(random) < 0.2});
  const PrCurve curve = precisionRecall(pairs);
  const double rate = static_cast<double>(curve.positives) / static_cast<double>(pairs.size());
  EXPECT_NEAR(curve.average_precision, rate, 0.02);
}

TEST(PrecisionRecall, NoPositivesGiveNan) {
  const std::vector<ScoredPair> pairs = {{1, false}, {0, false}};
  EXPECT_TRUE(std::isnan(precisionRecall(pairs).average_precision));
}

}  // namespace
}  // namespace segslam::eval
