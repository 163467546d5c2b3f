#include "segslam/loop/consistency_check.h"

#include <gtest/gtest.h>

namespace segslam::loop {
namespace {

TEST(ConsistencyCheck, ConfirmsAPlaceSupportedByThreeConsecutiveQueries) {
  ConsistencyCheck check(3);
  EXPECT_TRUE(check.update({{10, {9, 10, 11}}}).empty());
  EXPECT_TRUE(check.update({{12, {11, 12, 13}}}).empty());
  EXPECT_EQ(check.update({{13, {12, 13, 14}}}), std::vector<std::uint64_t>{13});
}

TEST(ConsistencyCheck, AQueryWithoutCandidatesBreaksTheChain) {
  ConsistencyCheck check(3);
  check.update({{10, {9, 10, 11}}});
  check.update({{11, {10, 11}}});
  check.update({});
  EXPECT_TRUE(check.update({{12, {11, 12}}}).empty());
}

TEST(ConsistencyCheck, UnrelatedPlacesDoNotSupportEachOther) {
  ConsistencyCheck check(3);
  check.update({{10, {10, 11}}});
  check.update({{40, {40, 41}}});
  EXPECT_TRUE(check.update({{70, {70, 71}}}).empty());
  // The second place of a query that also proposes a supported one still counts.
  check.reset();
  check.update({{10, {10, 11}}, {50, {50}}});
  check.update({{11, {11, 12}}});
  EXPECT_EQ(check.update({{80, {80}}, {12, {12, 13}}}), std::vector<std::uint64_t>{12});
}

}  // namespace
}  // namespace segslam::loop
