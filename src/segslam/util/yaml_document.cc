#include "segslam/util/yaml_document.h"

#include <fmt/format.h>

#include <algorithm>

namespace segslam::util {

YAML::Node parseYaml(std::string_view text, const std::filesystem::path& file) {
  try {
    return YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    failAt(file, e.mark.line + 1, fmt::format("malformed YAML: {}", e.msg));
  }
}

int yamlLine(const YAML::Node& node) { return node.Mark().line + 1; }

void rejectUnknownYamlKeys(const YAML::Node& mapping, std::span<const std::string_view> known,
                           const std::string& prefix, const std::filesystem::path& file) {
  for (const auto& entry : mapping) {
    const YAML::Node& key = entry.first;
    const bool is_known =
        key.IsScalar() && std::find(known.begin(), known.end(), key.Scalar()) != known.end();
    if (!is_known) {
      failAt(file, yamlLine(key),
             fmt::format("{}{} is not a known key (known: {})", prefix,
                         key.IsScalar() ? key.Scalar() : std::string("<not a scalar>"),
                         fmt::join(known, ", ")));
    }
  }
}

}  // namespace segslam::util
