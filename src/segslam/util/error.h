#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace segslam::util {

// The one exception type for bad input. Its message is a complete, single-line diagnostic that
// names the offending file (and line, when there is one), so the CLI can print it verbatim.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message);
};

// Builds "path:line: message" (line 0 means "no line": "path: message").
[[noreturn]] void failAt(const std::filesystem::path& file, int line, const std::string& message);
[[noreturn]] void failAt(const std::filesystem::path& file, const std::string& message);

}  // namespace segslam::util
