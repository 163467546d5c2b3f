#include "segslam/place/bow_database.h"

#include <gtest/gtest.h>

#include "segslam/place/place_test_descriptors.h"
#include "segslam/place/vocabulary.h"

namespace segslam::place {
namespace {

TEST(BowDatabaseTest, QueryFindsTheSameImageFirst) {
  const auto sets = testing::clusteredDescriptorSets(3, 3, 20, 21);
  VocabularyOptions options;
  options.k = 3;
  options.depth = 2;
  const auto vocabulary = Vocabulary::train(sets, options);
  BowDatabase database;
  // Images made of two variants each, so that images share words with their neighbours.
  std::vector<BowVector> images;
  for (std::size_t i = 0; i + 1 < sets.size(); ++i) {
    cv::Mat descriptors;
    cv::vconcat(sets[i], sets[i + 1], descriptors);
    images.push_back(vocabulary.transform(descriptors));
    EXPECT_EQ(database.add(images.back()), i);
  }
  for (std::size_t i = 0; i < images.size(); ++i) {
    const auto results = database.query(images[i], 3);
    ASSERT_FALSE(results.empty());
    EXPECT_EQ(results[0].entry, i);
    EXPECT_NEAR(results[0].score, 1.0, 1e-9);
    for (const auto& result : results) {
      EXPECT_NEAR(result.score, l1Score(images[i], images[result.entry]), 1e-9);
    }
  }
}

TEST(BowDatabaseTest, QueryRanksByScoreAndSkipsDisjointEntries) {
  BowDatabase database;
  database.add({{1, 1.0}, {2, 1.0}});            // 0: half shared with the query
  database.add({{3, 1.0}});                      // 1: disjoint
  database.add({{1, 1.0}, {2, 1.0}, {4, 2.0}});  // 2: a quarter shared
  const BowVector query{{1, 1.0}};
  const auto results = database.query(query, 10);
  ASSERT_EQ(results.size(), 2U);
  EXPECT_EQ(results[0].entry, 0U);
  EXPECT_DOUBLE_EQ(results[0].score, 0.5);
  EXPECT_EQ(results[1].entry, 2U);
  EXPECT_DOUBLE_EQ(results[1].score, 0.25);
}

TEST(BowDatabaseTest, ExclusionAndMaxResults) {
  BowDatabase database;
  for (int i = 0; i < 5; ++i) database.add({{1, 1.0}, {static_cast<WordId>(10 + i), 1.0}});
  const auto results =
      database.query({{1, 1.0}}, 2, [](BowDatabase::EntryId entry) { return entry < 2; });
  ASSERT_EQ(results.size(), 2U);
  EXPECT_EQ(results[0].entry, 2U);  // equal scores: lower entry first
  EXPECT_EQ(results[1].entry, 3U);
}

TEST(BowDatabaseTest, KeepsFeatureVectors) {
  BowDatabase database;
  const auto entry = database.add({{1, 2.0}}, FeatureVector{{7, {0, 3}}});
  EXPECT_EQ(database.featureVector(entry).at(7), (std::vector<int>{0, 3}));
  EXPECT_DOUBLE_EQ(database.bowVector(entry).at(1), 1.0);
}

TEST(BowDatabaseTest, RemovedEntriesAreNeverFoundAgainAndFreeTheirVectors) {
  BowDatabase database;
  database.add({{1, 1.0}, {2, 1.0}});
  database.add({{1, 1.0}, {3, 1.0}}, FeatureVector{{7, {0}}});
  database.add({{3, 1.0}});
  database.remove(1);
  const auto results = database.query({{1, 1.0}, {3, 1.0}}, 5);
  ASSERT_EQ(results.size(), 2U);
  for (const auto& result : results) EXPECT_NE(result.entry, 1U);
  EXPECT_TRUE(database.bowVector(1).empty());
  EXPECT_TRUE(database.featureVector(1).empty());
  EXPECT_EQ(database.add({{1, 1.0}}), 3U);  // ids are not reused
}

}  // namespace
}  // namespace segslam::place
