#include "segslam/place/vocabulary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "segslam/place/place_test_descriptors.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::place {
namespace {

using place::testing::clusteredDescriptorSets;
using place::testing::randomDescriptors;

VocabularyOptions smallTree(int k, int depth, std::uint64_t seed = 1) {
  VocabularyOptions options;
  options.k = k;
  options.depth = depth;
  options.seed = seed;
  return options;
}

std::string readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

void expectLoadErrorNaming(const std::filesystem::path& file, const std::string& what) {
  try {
    (void)Vocabulary::load(file);
    FAIL() << "no error for " << what;
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(VocabularyTest, MajorityCentreTakesTheBitsSetInMostDescriptors) {
  OrbDescriptor ones;
  ones.fill(0xFF);
  OrbDescriptor zeros{};
  OrbDescriptor first_half{};
  for (int i = 0; i < 16; ++i) first_half[static_cast<std::size_t>(i)] = 0xFF;
  const OrbDescriptor centre = majorityCentre({ones.data(), zeros.data(), first_half.data()});
  EXPECT_EQ(centre, first_half);
  // A tie is not a majority.
  EXPECT_EQ(majorityCentre({ones.data(), zeros.data()}), zeros);
}

TEST(VocabularyTest, MajorityCentreOfSingleBits) {
  OrbDescriptor a{};
  OrbDescriptor b{};
  OrbDescriptor c{};
  a[3] = 0b0000'0101;
  b[3] = 0b0000'0100;
  c[3] = 0b0000'0001;
  OrbDescriptor expected{};
  expected[3] = 0b0000'0101;
  EXPECT_EQ(majorityCentre({a.data(), b.data(), c.data()}), expected);
}

TEST(VocabularyTest, TrainingIsDeterministicForASeed) {
  const std::vector<cv::Mat> sets{randomDescriptors(400, 1), randomDescriptors(400, 2),
                                  randomDescriptors(400, 3)};
  const auto first = Vocabulary::train(sets, smallTree(4, 3, 7));
  const auto second = Vocabulary::train(sets, smallTree(4, 3, 7));
  EXPECT_TRUE(first == second);
  EXPECT_GT(first.numWords(), 16U);
  EXPECT_LE(first.numWords(), 64U);
}

TEST(VocabularyTest, RecoversTwoLevelClusters) {
  const auto sets = clusteredDescriptorSets(3, 3, 20, 11);
  const auto vocabulary = Vocabulary::train(sets, smallTree(3, 2));
  ASSERT_EQ(vocabulary.numWords(), 9U);
  std::set<WordId> words_of_sets;
  for (const cv::Mat& set : sets) {
    const WordId word = vocabulary.wordOf(set.ptr<std::uint8_t>(0));
    for (int row = 1; row < set.rows; ++row) {
      EXPECT_EQ(vocabulary.wordOf(set.ptr<std::uint8_t>(row)), word);
    }
    words_of_sets.insert(word);
  }
  EXPECT_EQ(words_of_sets.size(), 9U);
  // Each word appears in one of the nine images.
  for (WordId word = 0; word < 9; ++word) EXPECT_NEAR(vocabulary.idf(word), std::log(9.0), 1e-6);
}

TEST(VocabularyTest, TrainingDescriptorLandsInTheLeafOfItsCentre) {
  const auto sets = clusteredDescriptorSets(3, 3, 20, 13);
  const auto vocabulary = Vocabulary::train(sets, smallTree(3, 2));
  for (const cv::Mat& set : sets) {
    std::vector<const std::uint8_t*> members;
    for (int row = 0; row < set.rows; ++row) members.push_back(set.ptr<std::uint8_t>(row));
    const OrbDescriptor centre = majorityCentre(members);
    const WordId word = vocabulary.wordOf(centre.data());
    EXPECT_EQ(vocabulary.nodes()[vocabulary.wordNode(word)].centre, centre);
    for (const std::uint8_t* member : members) EXPECT_EQ(vocabulary.wordOf(member), word);
  }
}

TEST(VocabularyTest, EveryTrainingDescriptorFindsAWordSeenInTraining) {
  const std::vector<cv::Mat> sets{randomDescriptors(300, 4), randomDescriptors(300, 5)};
  const auto vocabulary = Vocabulary::train(sets, smallTree(5, 3));
  std::set<WordId> used;
  for (const cv::Mat& set : sets) {
    for (int row = 0; row < set.rows; ++row)
      used.insert(vocabulary.wordOf(set.ptr<std::uint8_t>(row)));
  }
  // Training ends each split on a nearest-centre assignment, so transform() retraces it and
  // every leaf holds at least one training descriptor.
  EXPECT_EQ(used.size(), vocabulary.numWords());
}

TEST(VocabularyTest, TransformIsNormalisedAndFeatureVectorCoversEveryKeypoint) {
  const auto sets = clusteredDescriptorSets(3, 3, 20, 12);
  const auto vocabulary = Vocabulary::train(sets, smallTree(3, 2));
  cv::Mat query;
  cv::vconcat(sets[0], sets[4], query);
  FeatureVector features;
  const BowVector bow = vocabulary.transform(query, features, 1);
  ASSERT_EQ(bow.size(), 2U);
  EXPECT_NEAR(bow.begin()->second + bow.rbegin()->second, 1.0, 1e-12);
  std::size_t indexed = 0;
  for (const auto& [node, rows] : features) {
    EXPECT_EQ(vocabulary.nodes()[node].level, 1);
    indexed += rows.size();
  }
  EXPECT_EQ(indexed, static_cast<std::size_t>(query.rows));
  EXPECT_EQ(features.size(), 2U);  // sets 0 and 4 lie under different top-level prototypes
}

TEST(VocabularyTest, RejectsBadOptionsAndInput) {
  const std::vector<cv::Mat> sets{randomDescriptors(50, 1)};
  EXPECT_THROW((void)Vocabulary::train(sets, smallTree(1, 3)), std::invalid_argument);
  EXPECT_THROW((void)Vocabulary::train(sets, smallTree(4, 0)), std::invalid_argument);
  EXPECT_THROW((void)Vocabulary::train({}, smallTree(4, 2)), std::invalid_argument);
  EXPECT_THROW((void)Vocabulary::train({cv::Mat(3, 16, CV_8UC1)}, smallTree(4, 2)),
               std::invalid_argument);
}

TEST(VocabularyTest, ShippedVocabularyLoads) {
  const auto file = std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config" / kDefaultVocabularyFile;
  const auto vocabulary = Vocabulary::load(file);
  EXPECT_EQ(vocabulary.k(), 10);
  EXPECT_EQ(vocabulary.depth(), 4);
  EXPECT_GT(vocabulary.numWords(), 5000U);
  EXPECT_GT(vocabulary.trainingSummary().descriptors, 100000U);
}

class VocabularyFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    VocabularyTrainingSummary summary{2, 600, "random test descriptors"};
    vocabulary_.emplace(Vocabulary::train({randomDescriptors(300, 8), randomDescriptors(300, 9)},
                                          smallTree(4, 3), summary));
    file_ = dir_.path() / "test.voc";
    vocabulary_->save(file_);
  }

  segslam::testing::ScopedTempDir dir_;
  std::optional<Vocabulary> vocabulary_;
  std::filesystem::path file_;
};

TEST_F(VocabularyFileTest, SaveLoadRoundTripIsIdentical) {
  const auto loaded = Vocabulary::load(file_);
  EXPECT_TRUE(loaded == *vocabulary_);
  EXPECT_EQ(loaded.trainingSummary().description, "random test descriptors");
  EXPECT_EQ(loaded.trainingSummary().descriptors, 600U);
  const cv::Mat query = randomDescriptors(100, 10);
  EXPECT_EQ(loaded.transform(query), vocabulary_->transform(query));
}

TEST_F(VocabularyFileTest, TruncatedFileIsAnError) {
  const std::string bytes = readBytes(file_);
  for (const std::size_t size :
       {std::size_t{0}, std::size_t{10}, bytes.size() / 2, bytes.size() - 1}) {
    writeBytes(file_, bytes.substr(0, size));
    expectLoadErrorNaming(file_, "truncated");
  }
}

TEST_F(VocabularyFileTest, WrongMagicIsAnError) {
  std::string bytes = readBytes(file_);
  bytes[0] = 'X';
  writeBytes(file_, bytes);
  expectLoadErrorNaming(file_, "wrong magic");
}

TEST_F(VocabularyFileTest, WrongVersionIsAnError) {
  std::string bytes = readBytes(file_);
  bytes[8] = 99;
  writeBytes(file_, bytes);
  expectLoadErrorNaming(file_, "version 99");
}

TEST_F(VocabularyFileTest, TrailingBytesAreAnError) {
  writeBytes(file_, readBytes(file_) + "x");
  expectLoadErrorNaming(file_, "corrupt");
}

TEST_F(VocabularyFileTest, InconsistentTreeIsAnError) {
  std::string bytes = readBytes(file_);
  // The root's child count: after magic, version, descriptor size, k, depth, images,
  // descriptors, description (size + text) and node count comes the root's centre.
  const std::size_t root = 8 + 4 * 4 + 2 * 8 + 4 + 23 + 4;
  bytes[root + 32] = 9;  // more children than k = 4
  writeBytes(file_, bytes);
  expectLoadErrorNaming(file_, "corrupt");
}

TEST_F(VocabularyFileTest, MissingFileIsAnError) {
  expectLoadErrorNaming(dir_.path() / "absent.voc", "cannot open");
}

}  // namespace
}  // namespace segslam::place
