#include "segslam/place/bow_vector.h"

#include <gtest/gtest.h>

namespace segslam::place {
namespace {

TEST(BowVectorTest, IdenticalVectorsScoreOne) {
  const BowVector a{{1, 0.2}, {5, 0.3}, {9, 0.5}};
  EXPECT_DOUBLE_EQ(l1Score(a, a), 1.0);
}

TEST(BowVectorTest, ScoreIgnoresScale) {
  const BowVector a{{1, 0.2}, {5, 0.8}};
  const BowVector b{{1, 2.0}, {5, 8.0}};
  EXPECT_NEAR(l1Score(a, b), 1.0, 1e-12);
}

TEST(BowVectorTest, DisjointVectorsScoreZero) {
  const BowVector a{{1, 0.5}, {2, 0.5}};
  const BowVector b{{3, 0.5}, {4, 0.5}};
  EXPECT_DOUBLE_EQ(l1Score(a, b), 0.0);
}

TEST(BowVectorTest, HalfSharedWeightScoresHalf) {
  const BowVector a{{1, 0.5}, {2, 0.5}};
  const BowVector b{{1, 0.5}, {3, 0.5}};
  EXPECT_DOUBLE_EQ(l1Score(a, b), 0.5);
  EXPECT_DOUBLE_EQ(l1Score(b, a), 0.5);
}

TEST(BowVectorTest, EmptyVectorScoresZero) {
  const BowVector a{{1, 1.0}};
  EXPECT_DOUBLE_EQ(l1Score(a, BowVector{}), 0.0);
  EXPECT_DOUBLE_EQ(l1Score(BowVector{}, BowVector{}), 0.0);
}

TEST(BowVectorTest, NormaliseL1SumsToOne) {
  BowVector a{{1, 1.0}, {2, 3.0}};
  normaliseL1(a);
  EXPECT_DOUBLE_EQ(a[1], 0.25);
  EXPECT_DOUBLE_EQ(a[2], 0.75);
}

}  // namespace
}  // namespace segslam::place
