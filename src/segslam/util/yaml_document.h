#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "segslam/util/error.h"

// Reading YAML settings files with diagnostics that name the file and line, shared by every
// settings file segslam reads (camera, segmentation models).
namespace segslam::util {

// Parses `text`; a syntax error becomes a util::Error "file:line: malformed YAML: ...".
YAML::Node parseYaml(std::string_view text, const std::filesystem::path& file);

// 1-based line of a node in its file.
int yamlLine(const YAML::Node& node);

// The node's value as T; a wrong type becomes "file:line: <label> has the wrong type: '<value>'".
template <typename T>
T yamlValue(const YAML::Node& node, const std::string& label, const std::filesystem::path& file) {
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    failAt(file, yamlLine(node),
           label + " has the wrong type: '" +
               (node.IsScalar() ? node.Scalar() : std::string("<not a scalar>")) + "'");
  }
}

// A misspelt key would otherwise be ignored silently, leaving a default in place: every key of
// `mapping` must be one of `known`. `prefix` names the mapping in messages ("camera.").
void rejectUnknownYamlKeys(const YAML::Node& mapping, std::span<const std::string_view> known,
                           const std::string& prefix, const std::filesystem::path& file);

}  // namespace segslam::util
