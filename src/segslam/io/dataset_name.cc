#include "segslam/io/dataset_name.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace segslam::io {

std::string datasetFolderName(const std::filesystem::path& dataset_folder) {
  std::error_code ec;
  std::filesystem::path folder = std::filesystem::weakly_canonical(dataset_folder, ec);
  if (ec) folder = dataset_folder.lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();
  std::string name = folder.filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name;
}

bool hasNameToken(std::string_view name, std::string_view token) {
  const auto is_alnum = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
  const auto is_digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  const auto same_kind = [&](char a, char b) {
    return is_digit(a) ? is_digit(b) : is_alnum(b) && !is_digit(b);
  };
  if (token.empty()) return false;
  for (std::size_t at = name.find(token); at != std::string_view::npos;
       at = name.find(token, at + 1)) {
    const std::size_t end = at + token.size();
    if (at > 0 && is_alnum(name[at - 1])) continue;
    if (end < name.size() && same_kind(token.back(), name[end])) continue;
    return true;
  }
  return false;
}

}  // namespace segslam::io
