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
// lines starting with '#' are skipped. Line numbers are kept for error messages.
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

// Throws Error("file:line: duplicated timestamp ...") or ("... out of order ...") unless
// `timestamp` is larger than `previous`: TUM lists and trajectories are sorted by time.
void requireIncreasingTimestamp(double previous, double timestamp,
                                const std::filesystem::path& file, int line);

}  // namespace segslam::util
