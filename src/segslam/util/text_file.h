#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace segslam::util {

// One non-empty, non-comment line of a whitespace/comma separated text file.
struct TextRow {
  int line = 0;  // 1-based line number in the file
  std::vector<std::string> fields;
};

// Splits text the way the TUM RGB-D tools do: commas and tabs count as spaces, blank lines and
// lines starting with '#' are skipped. Line numbers are kept for error messages. A UTF-8 byte
// order mark (which Windows editors put first) is not content and is dropped.
std::vector<TextRow> parseTextRows(std::string_view text);

// Reads a whole file; throws Error naming the file when it is missing or cannot be read.
std::string readTextFile(const std::filesystem::path& file);

// Reads and parses a whole file; throws Error naming the file when it cannot be read.
std::vector<TextRow> readTextRows(const std::filesystem::path& file);

// Strict number parsing for one field: the whole field must be a finite number.
// Throws Error("file:line: <what> is not a number: '<field>'").
double parseDouble(const std::string& field, const std::filesystem::path& file, int line,
                   std::string_view what);

// Throws unless the row has at least `min_fields` fields.
void requireFields(const TextRow& row, std::size_t min_fields, const std::filesystem::path& file,
                   std::string_view expected_format);

// Throws unless the row has exactly `count` fields: an extra field is as suspicious as a missing
// one (a file name with a space, two lines run together).
void requireFieldCount(const TextRow& row, std::size_t count, const std::filesystem::path& file,
                       std::string_view expected_format);

// Which rows of a TUM list to keep, the way the TUM tools' read_file_list keeps them: it turns
// the list into a Python dict keyed by timestamp, so of a duplicated timestamp the later line
// wins, and the tools sort the keys, so the order of the lines does not matter.
struct TimestampKeyedRows {
  std::vector<std::size_t> rows;  // indices into the input, one per timestamp, by increasing time
  // What was repaired, naming the file and the first offending line; empty when nothing was.
  std::string warning;
};

// `stamps[k]` is the timestamp of the row on line `lines[k]` of `file` (the same size).
TimestampKeyedRows keyRowsByTimestamp(const std::vector<double>& stamps,
                                      const std::vector<int>& lines,
                                      const std::filesystem::path& file);

}  // namespace segslam::util
