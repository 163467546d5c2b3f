#include "segslam/io/image_list.h"

#include <gtest/gtest.h>

#include "segslam/io/io_test_support.h"
#include "segslam/testing/test_support.h"

namespace segslam::io {
namespace {

using testing::errorMessage;

std::string listError(std::string_view text) {
  return errorMessage([&] { (void)parseImageList(text, "d/rgb.txt"); });
}

std::string associationError(std::string_view text) {
  return errorMessage([&] { (void)parseAssociationList(text, "d/associations.txt"); });
}

TEST(TumDatasetImageList, ParsesEntriesWithTheirLines) {
  const auto entries = parseImageList(
      "# color images\n# timestamp filename\n1305031102.175304 rgb/1305031102.175304.jpg\n\n"
      "1305031102.211214\trgb/b.png\r\n",
      "rgb.txt");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].line, 3);
  EXPECT_DOUBLE_EQ(entries[0].timestamp, 1305031102.175304);
  EXPECT_EQ(entries[0].path, "rgb/1305031102.175304.jpg");
  EXPECT_EQ(entries[1].line, 5);
  EXPECT_EQ(entries[1].path, "rgb/b.png");
  EXPECT_TRUE(parseImageList("# only a comment\n", "rgb.txt").empty());
}

TEST(TumDatasetImageList, MalformedLinesNameFileAndLine) {
  EXPECT_EQ(listError("1.0 a.png\n2.0\n"),
            "d/rgb.txt:2: expected 'timestamp filename' but found 1 field(s)");
  EXPECT_EQ(listError("1.0 a.png extra\n"),
            "d/rgb.txt:1: expected 'timestamp filename' but found 3 field(s)");
  EXPECT_EQ(listError("# c\nabc a.png\n"), "d/rgb.txt:2: timestamp is not a finite number: 'abc'");
  EXPECT_EQ(listError("nan a.png\n"), "d/rgb.txt:1: timestamp is not a finite number: 'nan'");
}

// associate.py reads lists with read_file_list: a dict keyed by timestamp, sorted later.
TEST(TumDatasetImageList, DuplicatedAndUnorderedTimestampsAreReadLikeTheTumTools) {
  testing::CapturedLog log;
  const auto entries =
      parseImageList("2.0 c.png\n1.0 a.png\n1.0 b.png\n\n1.5 d.png\n", "d/rgb.txt");
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].path, "b.png");
  EXPECT_EQ(entries[0].line, 3);
  EXPECT_EQ(entries[1].path, "d.png");
  EXPECT_EQ(entries[2].path, "c.png");
  EXPECT_EQ(log.text(),
            "[warning] d/rgb.txt:3: 1 duplicated timestamp (first 1): the later line of each is "
            "used; d/rgb.txt:2: 1 timestamp out of order (first 1 after 2): the lines are sorted "
            "by time, as the TUM benchmark tools do\n");
}

TEST(TumDatasetImageList, ReadsFilesAndNamesMissingOnes) {
  segslam::testing::ScopedTempDir temp;
  testing::writeText(temp.path() / "depth.txt", "1.0 depth/a.png\n");
  EXPECT_EQ(readImageList(temp.path() / "depth.txt").size(), 1u);
  EXPECT_EQ(errorMessage([&] { (void)readImageList(temp.path() / "mask.txt"); }),
            (temp.path() / "mask.txt").string() + ": file not found");
}

TEST(TumDatasetImageList, ParsesAssociations) {
  const auto entries = parseAssociationList(
      "# associate.py\n1.0 rgb/a.png 0.99 depth/a.png\n2.0 rgb/b.png 1.5 depth/b.png\n",
      "associations.txt");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1].rgb.line, 3);
  EXPECT_DOUBLE_EQ(entries[1].rgb.timestamp, 2.0);
  EXPECT_EQ(entries[1].rgb.path, "rgb/b.png");
  EXPECT_DOUBLE_EQ(entries[1].depth.timestamp, 1.5);
  EXPECT_EQ(entries[1].depth.path, "depth/b.png");
}

TEST(TumDatasetImageList, DepthOfAssociationsMayCrossButNotRepeat) {
  EXPECT_EQ(parseAssociationList("1.0 a 1.1 x\n1.05 b 1.0 y\n", "a.txt").size(), 2u);
  EXPECT_EQ(associationError("1.0 a 1.1 x\n1.05 b 1.0 y\n1.1 c 1.1 z\n"),
            "d/associations.txt:3: depth timestamp 1.1 is already used on line 1");
}

TEST(TumDatasetImageList, AssociationsAreKeyedByTheirColourTimestamps) {
  testing::CapturedLog log;
  // The repeated line's depth timestamp is not used twice: only the later line of 1.0 is kept.
  const auto entries =
      parseAssociationList("2.0 c 2.0 z\n1.0 a 1.0 x\n1.0 b 1.0 x\n", "d/associations.txt");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].rgb.path, "b");
  EXPECT_EQ(entries[1].rgb.path, "c");
  EXPECT_EQ(entries[1].depth.path, "z");
  EXPECT_EQ(log.text(),
            "[warning] d/associations.txt:3: 1 duplicated timestamp (first 1): the later line of "
            "each is used; d/associations.txt:2: 1 timestamp out of order (first 1 after 2): the "
            "lines are sorted by time, as the TUM benchmark tools do\n");
}

TEST(TumDatasetImageList, MalformedAssociationsNameFileAndLine) {
  EXPECT_EQ(associationError("1.0 a.png 1.0\n"),
            "d/associations.txt:1: expected 'rgb_timestamp rgb_file depth_timestamp depth_file' "
            "but found 3 field(s)");
  EXPECT_EQ(associationError("1.0 a.png x d.png\n"),
            "d/associations.txt:1: timestamp is not a finite number: 'x'");
}

}  // namespace
}  // namespace segslam::io
