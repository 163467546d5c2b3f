#include "segslam/viewer/served_file.h"

#include <algorithm>
#include <system_error>

namespace segslam::viewer {

namespace {

namespace fs = std::filesystem;

bool isInside(const fs::path& folder, const fs::path& file) {
  const auto [folder_end, file_at] =
      std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
  return folder_end == folder.end() && file_at != file.end();
}

}  // namespace

bool mayServe(const ServedFolder& served, std::string_view url_path) {
  if (!url_path.starts_with(served.url_prefix)) return true;
  std::string relative(url_path.substr(served.url_prefix.size()));
  // httplib answers a folder's URL with its index.html.
  if (relative.empty() || relative.back() == '/') relative += "index.html";
  const fs::path requested = served.folder / fs::path(relative).relative_path();
  std::error_code error;
  // Absent: the server answers 404. A dangling link is present, and canonical() refuses it.
  if (!fs::exists(fs::symlink_status(requested, error))) return true;
  const fs::path real_file = fs::canonical(requested, error);
  if (error) return false;
  const fs::path real_folder = fs::canonical(served.folder, error);
  if (error) return false;
  return fs::is_regular_file(real_file, error) && isInside(real_folder, real_file);
}

}  // namespace segslam::viewer
