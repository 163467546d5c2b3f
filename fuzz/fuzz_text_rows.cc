// util::parseTextRows never fails; its rows must be well formed. util::parseDouble on any field
// either returns a finite number or throws util::Error.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "segslam/util/error.h"
#include "segslam/util/text_file.h"

namespace {

using segslam::fuzz::check;

bool hasSeparatorOrNewline(std::string_view field) {
  return field.find_first_of(" \t,\r\n") != std::string_view::npos;
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string_view::npos;
       start = end + 1, end = text.find('\n', start)) {
    lines.push_back(text.substr(start, end - start));
  }
  lines.push_back(text.substr(start));
  return lines;
}

void checkField(const std::string& field, int line) {
  check(!field.empty(), "fields are not empty");
  check(!hasSeparatorOrNewline(field), "fields contain no separators");
  try {
    const double value = segslam::util::parseDouble(field, "fuzz.txt", line, "field");
    check(std::isfinite(value), "parsed numbers are finite");
  } catch (const segslam::util::Error&) {
    // Rejected fields are the expected outcome for most inputs.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto rows = segslam::util::parseTextRows(text);
  const std::vector<std::string_view> lines = splitLines(text);
  int previous_line = 0;
  for (const auto& row : rows) {
    check(row.line > previous_line, "line numbers increase");
    check(row.line <= static_cast<int>(lines.size()), "line numbers exist");
    // As in the TUM tools, only a '#' in the first column makes a comment: " # x" is a row.
    check(!lines[row.line - 1].starts_with('#'), "comment lines are skipped");
    check(!row.fields.empty(), "rows have fields");
    for (const auto& field : row.fields) checkField(field, row.line);
    previous_line = row.line;
  }
  return 0;
}
