#include "segslam/util/error.h"

#include <fmt/format.h>

namespace segslam::util {

Error::Error(const std::string& message) : std::runtime_error(message) {}

void failAt(const std::filesystem::path& file, int line, const std::string& message) {
  if (line > 0) throw Error(fmt::format("{}:{}: {}", file.string(), line, message));
  throw Error(fmt::format("{}: {}", file.string(), message));
}

void failAt(const std::filesystem::path& file, const std::string& message) {
  failAt(file, 0, message);
}

}  // namespace segslam::util
