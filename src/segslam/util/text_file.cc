#include "segslam/util/text_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "segslam/util/error.h"

namespace segslam::util {

namespace {

bool isSeparator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; }

std::vector<std::string> splitFields(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSeparator(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isSeparator(line[i])) ++i;
    if (i > start) fields.emplace_back(line.substr(start, i - start));
  }
  return fields;
}

}  // namespace

std::vector<TextRow> parseTextRows(std::string_view text) {
  std::vector<TextRow> rows;
  int line_number = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    ++line_number;
    pos = end + 1;
    if (line.empty() || line.front() == '#') continue;
    auto fields = splitFields(line);
    if (!fields.empty()) rows.push_back({line_number, std::move(fields)});
  }
  return rows;
}

std::string readTextFile(const std::filesystem::path& file) {
  std::error_code ec;  // the error_code overloads: a failed status check must not throw
  if (std::filesystem::is_directory(file, ec)) failAt(file, "is a folder, not a file");
  std::ifstream in(file, std::ios::binary);
  if (!in) failAt(file, std::filesystem::exists(file, ec) ? "cannot be read" : "file not found");
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) failAt(file, "read error");
  return std::move(content).str();
}

std::vector<TextRow> readTextRows(const std::filesystem::path& file) {
  return parseTextRows(readTextFile(file));
}

double parseDouble(const std::string& field, const std::filesystem::path& file, int line,
                   std::string_view what) {
  double value = 0.0;
  const char* first = field.data();
  const char* last = field.data() + field.size();
  // from_chars rejects a leading '+', which hand-written files use; "+-1" must still fail.
  if (last - first > 1 && first[0] == '+' && first[1] != '-') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || !std::isfinite(value)) {
    failAt(file, line, fmt::format("{} is not a finite number: '{}'", what, field));
  }
  return value;
}

void requireFields(const TextRow& row, std::size_t min_fields, const std::filesystem::path& file,
                   std::string_view expected_format) {
  if (row.fields.size() < min_fields) {
    failAt(file, row.line,
           fmt::format("expected '{}' but found {} field(s)", expected_format, row.fields.size()));
  }
}

void requireFieldCount(const TextRow& row, std::size_t count, const std::filesystem::path& file,
                       std::string_view expected_format) {
  if (row.fields.size() != count) {
    failAt(file, row.line,
           fmt::format("expected '{}' but found {} field(s)", expected_format, row.fields.size()));
  }
}

void requireIncreasingTimestamp(double previous, double timestamp,
                                const std::filesystem::path& file, int line) {
  if (timestamp == previous) failAt(file, line, fmt::format("duplicated timestamp {}", timestamp));
  if (timestamp < previous) {
    failAt(file, line,
           fmt::format("timestamp {} is out of order (previous {})", timestamp, previous));
  }
}

}  // namespace segslam::util
