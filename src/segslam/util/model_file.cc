#include "segslam/util/model_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>
#include <vector>

#include "segslam/util/error.h"

namespace segslam::util {

std::filesystem::path findModelFile(const std::filesystem::path& model,
                                    const std::filesystem::path& config_file,
                                    const std::optional<std::filesystem::path>& override_file,
                                    const std::string& kind, const std::string& override_flag) {
  if (override_file) {
    if (!std::filesystem::is_regular_file(*override_file)) {
      failAt(*override_file, kind + " file not found");
    }
    return *override_file;
  }
  std::vector<std::filesystem::path> tried;
  tried.push_back(model.is_absolute() ? model : config_file.parent_path() / model);
  if (const char* dir = std::getenv("SEGSLAM_MODEL_DIR"); dir && *dir) {
    tried.push_back(std::filesystem::path(dir) / model.filename());
  }
  for (const auto& candidate : tried) {
    if (std::filesystem::is_regular_file(candidate)) return candidate;
  }
  std::vector<std::string> names;
  for (const auto& candidate : tried) names.push_back(candidate.string());
  failAt(config_file, fmt::format("{} '{}' not found (tried {}; pass {} FILE or set "
                                  "SEGSLAM_MODEL_DIR)",
                                  kind, model.string(), fmt::join(names, ", "), override_flag));
}

}  // namespace segslam::util
