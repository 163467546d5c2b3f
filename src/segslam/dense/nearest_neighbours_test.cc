#include "segslam/dense/nearest_neighbours.h"

#include <gtest/gtest.h>

#include <random>

namespace segslam::dense {
namespace {

std::vector<Eigen::Vector3f> randomPoints(std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coordinate(0.0f, 1.0f);
  std::vector<Eigen::Vector3f> points(count);
  for (auto& p : points) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
  return points;
}

std::size_t bruteForceCountWithin(const std::vector<Eigen::Vector3f>& set,
                                  const std::vector<Eigen::Vector3f>& queries, double radius) {
  std::size_t count = 0;
  for (const auto& q : queries) {
    for (const auto& p : set) {
      if ((p - q).norm() <= radius) {
        ++count;
        break;
      }
    }
  }
  return count;
}

TEST(NearestNeighbours, CountsAsABruteForceSearchDoes) {
  const auto set = randomPoints(3000, 1);
  const auto queries = randomPoints(2000, 2);
  const NearestNeighbours index(set);
  const std::size_t expected = bruteForceCountWithin(set, queries, 0.03);
  EXPECT_GT(expected, 0u);
  EXPECT_LT(expected, queries.size());
  EXPECT_EQ(index.countWithin(queries, 0.03), expected);
}

// The index must not depend on the caller's points, nor on the temporary copy it is built from:
// Open3D's tree reads the coordinates it was given, and a freed copy was reused by later
// allocations (map evaluation's completeness changed from run to run).
TEST(NearestNeighbours, KeepsItsOwnCopyOfThePoints) {
  auto set = randomPoints(3000, 3);
  const auto original = set;
  const auto queries = randomPoints(2000, 4);
  const NearestNeighbours index(set);
  set.assign(set.size(), Eigen::Vector3f(50.0f, 50.0f, 50.0f));
  std::vector<std::vector<double>> reuse;
  for (int i = 0; i < 16; ++i) reuse.emplace_back(3 * 3000, 1e6);
  EXPECT_EQ(index.countWithin(queries, 0.03), bruteForceCountWithin(original, queries, 0.03));
}

TEST(NearestNeighbours, AnEmptySetHasNothingWithinAnyRadius) {
  const NearestNeighbours index({});
  EXPECT_FALSE(index.anyWithin(Eigen::Vector3f::Zero(), 10.0));
  EXPECT_EQ(index.countWithin(randomPoints(10, 5), 10.0), 0u);
}

}  // namespace
}  // namespace segslam::dense
