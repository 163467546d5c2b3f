#include "segslam/util/text_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::util {
namespace {

TEST(TextFile, SplitsLikeTheTumTools) {
  const auto rows = parseTextRows("# comment\n\n1.0 a.png\n2.0,\tb.png\r\n  \n3 c d\n");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].line, 3);
  EXPECT_EQ(rows[0].fields, (std::vector<std::string>{"1.0", "a.png"}));
  EXPECT_EQ(rows[1].fields, (std::vector<std::string>{"2.0", "b.png"}));
  EXPECT_EQ(rows[2].line, 6);
  EXPECT_EQ(rows[2].fields.size(), 3u);
  // Only a '#' in the first column starts a comment (as in the TUM tools' read_file_list).
  const auto indented = parseTextRows(" # not a comment\n");
  ASSERT_EQ(indented.size(), 1u);
  EXPECT_EQ(indented[0].fields.front(), "#");
}

TEST(TextFile, ParseDoubleRejectsGarbageWithFileAndLine) {
  EXPECT_DOUBLE_EQ(parseDouble("1305031102.175304", "f.txt", 1, "timestamp"), 1305031102.175304);
  EXPECT_DOUBLE_EQ(parseDouble("+2.5e-1", "f.txt", 1, "x"), 0.25);
  try {
    parseDouble("12abc", "dir/rgb.txt", 7, "timestamp");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "dir/rgb.txt:7: timestamp is not a finite number: '12abc'");
  }
  EXPECT_THROW(parseDouble("nan", "f", 1, "x"), Error);
  EXPECT_THROW(parseDouble("inf", "f", 1, "x"), Error);
  EXPECT_THROW(parseDouble("", "f", 1, "x"), Error);
  EXPECT_THROW(parseDouble("+", "f", 1, "x"), Error);
  EXPECT_THROW(parseDouble("+-1", "f", 1, "x"), Error);
  EXPECT_THROW(parseDouble("1e999", "f", 1, "x"), Error);
  EXPECT_THROW(parseDouble("0x10", "f", 1, "x"), Error);
}

TEST(TextFile, MissingFileNamesTheFile) {
  try {
    readTextRows("/nonexistent/rgb.txt");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/rgb.txt: file not found");
  }
}

TEST(TextFile, ReadsWholeFilesAndRejectsFolders) {
  segslam::testing::ScopedTempDir temp;
  const auto file = temp.path() / "list.txt";
  std::ofstream(file) << "# c\n1 a\n";
  EXPECT_EQ(readTextFile(file), "# c\n1 a\n");
  EXPECT_EQ(readTextRows(file).front().line, 2);
  try {
    readTextFile(temp.path());
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.what(), temp.path().string() + ": is a folder, not a file");
  }
}

TEST(TextFile, FieldCountMustMatchExactly) {
  const TextRow row{4, {"1", "a", "b"}};
  EXPECT_NO_THROW(requireFieldCount(row, 3, "f.txt", "t a b"));
  EXPECT_NO_THROW(requireFields(row, 2, "f.txt", "t a"));
  try {
    requireFieldCount(row, 2, "f.txt", "t a");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "f.txt:4: expected 't a' but found 3 field(s)");
  }
  EXPECT_THROW(requireFieldCount(row, 4, "f.txt", "t a b c"), Error);
}

TEST(TextFile, ByteOrderMarkIsNotContent) {
  const auto rows = parseTextRows("\xEF\xBB\xBF# written on Windows\r\n1.0 a.png\r\n");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].line, 2);
  EXPECT_EQ(rows[0].fields, (std::vector<std::string>{"1.0", "a.png"}));
}

// read_file_list of the TUM tools builds a dict: a timestamp's later line wins; keys are sorted.
TEST(TextFile, RowsAreKeyedByTimestampLikeAPythonDict) {
  const auto keyed = keyRowsByTimestamp({3.0, 1.0, 2.0, 1.0, 3.0}, {1, 2, 3, 4, 5}, "f.txt");
  EXPECT_EQ(keyed.rows, (std::vector<std::size_t>{3, 2, 4}));  // 1.0 line 4, 2.0, 3.0 line 5
  EXPECT_EQ(keyed.warning,
            "f.txt:4: 2 duplicated timestamps (first 1): the later line of each is used; "
            "f.txt:2: 2 timestamps out of order (first 1 after 3): the lines are sorted by time, "
            "as the TUM benchmark tools do");
}

TEST(TextFile, OrderedUniqueRowsAreKeptAsTheyAreWithoutWarning) {
  const auto keyed = keyRowsByTimestamp({1.0, 1.5, 2.0}, {3, 4, 6}, "f.txt");
  EXPECT_EQ(keyed.rows, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_TRUE(keyed.warning.empty());
  EXPECT_TRUE(keyRowsByTimestamp({}, {}, "f.txt").rows.empty());
}

TEST(TextFile, OneKindOfRepairIsWarnedAlone) {
  const auto duplicated = keyRowsByTimestamp({1311868229.5, 1311868229.576, 1311868229.576},
                                             {10861, 10862, 10863}, "d/groundtruth.txt");
  EXPECT_EQ(duplicated.rows, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(duplicated.warning,
            "d/groundtruth.txt:10863: 1 duplicated timestamp (first 1311868229.576): the later "
            "line of each is used, as the TUM benchmark tools do");
  const auto unordered = keyRowsByTimestamp({1.0, 3.0, 2.0, 4.0}, {1, 2, 3, 4}, "f.txt");
  EXPECT_EQ(unordered.rows, (std::vector<std::size_t>{0, 2, 1, 3}));
  EXPECT_EQ(unordered.warning,
            "f.txt:3: 1 timestamp out of order (first 2 after 3): the lines are sorted by time, "
            "as the TUM benchmark tools do");
}

}  // namespace
}  // namespace segslam::util
