#include "segslam/util/output_folder.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "segslam/util/error.h"

namespace segslam::util {

namespace {

// create_directories reports a file in the way as "File exists", which reads as if the folder
// were there.
std::string whyNotCreated(const std::filesystem::path& folder, const std::error_code& error) {
  std::error_code ignored;
  if (std::filesystem::exists(folder, ignored) && !std::filesystem::is_directory(folder, ignored)) {
    return "a file of that name is in the way";
  }
  return error.message();
}

}  // namespace

void createOutputFolder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  std::error_code ignored;
  if (error || !std::filesystem::is_directory(folder, ignored)) {
    throw Error(fmt::format("cannot create output folder {}: {}", folder.string(),
                            whyNotCreated(folder, error)));
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    throw Error(fmt::format("cannot write into output folder {}: {}", folder.string(),
                            std::generic_category().message(errno)));
  }
}

void createFolderFor(const std::filesystem::path& file) {
  if (file.has_parent_path()) createOutputFolder(file.parent_path());
}

}  // namespace segslam::util
