#include "segslam/util/text_file.h"

#include <fmt/format.h>

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

std::vector<TextRow> readTextRows(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) failAt(file, std::filesystem::exists(file) ? "cannot be read" : "file not found");
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) failAt(file, "read error");
  return parseTextRows(content.str());
}

double parseDouble(const std::string& field, const std::filesystem::path& file, int line,
                   std::string_view what) {
  double value = 0.0;
  const char* first = field.data();
  const char* last = field.data() + field.size();
  if (!field.empty() && *first == '+') ++first;
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

}  // namespace segslam::util
