#pragma once

#include <filesystem>
#include <string_view>

namespace segslam::viewer {

// A folder served under a URL prefix (httplib's mount points: "/run/" -> the run folder).
struct ServedFolder {
  std::string_view url_prefix;
  std::filesystem::path folder;
};

// Whether a request for `url_path` (decoded, as the server sees it) under `served` may be answered
// from disk: false when the file it names exists but is not a regular file whose real path, links
// resolved, lies inside the folder's real path. A link out of the run folder (to /etc/passwd, to
// /) names a file outside it; paths the folder does not hold are left to the server (404).
[[nodiscard]] bool mayServe(const ServedFolder& served, std::string_view url_path);

}  // namespace segslam::viewer
