#include "segslam/util/text_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>
#include <unordered_set>

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

std::string_view plural(std::size_t count) { return count == 1 ? "" : "s"; }

struct FirstOffence {
  std::size_t count = 0;
  std::size_t row = 0;  // the first offending row
};

// Rows whose timestamp an earlier row already had: the rows a dict keeps the later line of.
FirstOffence repeatedTimestamps(const std::vector<double>& stamps) {
  FirstOffence repeated;
  std::unordered_set<double> seen;
  for (std::size_t k = 0; k < stamps.size(); ++k) {
    if (seen.insert(stamps[k]).second) continue;
    if (repeated.count++ == 0) repeated.row = k;
  }
  return repeated;
}

// Rows whose timestamp is smaller than the row's before them.
FirstOffence unorderedTimestamps(const std::vector<double>& stamps) {
  FirstOffence unordered;
  for (std::size_t k = 1; k < stamps.size(); ++k) {
    if (stamps[k] >= stamps[k - 1]) continue;
    if (unordered.count++ == 0) unordered.row = k;
  }
  return unordered;
}

std::string repairWarning(const std::vector<double>& stamps, const std::vector<int>& lines,
                          const std::filesystem::path& file) {
  const FirstOffence repeated = repeatedTimestamps(stamps);
  const FirstOffence unordered = unorderedTimestamps(stamps);
  std::vector<std::string> repairs;
  if (repeated.count > 0) {
    repairs.push_back(
        fmt::format("{}:{}: {} duplicated timestamp{} (first {}): the later line of "
                    "each is used",
                    file.string(), lines[repeated.row], repeated.count, plural(repeated.count),
                    stamps[repeated.row]));
  }
  if (unordered.count > 0) {
    repairs.push_back(
        fmt::format("{}:{}: {} timestamp{} out of order (first {} after {}): the "
                    "lines are sorted by time",
                    file.string(), lines[unordered.row], unordered.count, plural(unordered.count),
                    stamps[unordered.row], stamps[unordered.row - 1]));
  }
  if (repairs.empty()) return "";
  return fmt::format("{}, as the TUM benchmark tools do", fmt::join(repairs, "; "));
}

}  // namespace

std::vector<TextRow> parseTextRows(std::string_view text) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
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

TimestampKeyedRows keyRowsByTimestamp(const std::vector<double>& stamps,
                                      const std::vector<int>& lines,
                                      const std::filesystem::path& file) {
  std::vector<std::size_t> order(stamps.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return stamps[a] < stamps[b]; });
  TimestampKeyedRows keyed;
  for (std::size_t k = 0; k < order.size(); ++k) {
    // Stable: of equal timestamps the row of the later line comes last, and it is the one kept.
    const bool later_one_follows = k + 1 < order.size() && stamps[order[k + 1]] == stamps[order[k]];
    if (!later_one_follows) keyed.rows.push_back(order[k]);
  }
  keyed.warning = repairWarning(stamps, lines, file);
  return keyed;
}

}  // namespace segslam::util
