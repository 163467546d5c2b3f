#include "segslam/util/text_file.h"

#include <gtest/gtest.h>

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
}

TEST(TextFile, MissingFileNamesTheFile) {
  try {
    readTextRows("/nonexistent/rgb.txt");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/rgb.txt: file not found");
  }
}

}  // namespace
}  // namespace segslam::util
