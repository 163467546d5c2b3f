#include "segslam/segmentation/model_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "segslam/util/error.h"
#include "segslam/util/model_file.h"
#include "segslam/util/text_file.h"
#include "segslam/util/yaml_document.h"

namespace segslam::segmentation {

namespace {

constexpr std::string_view kRoot = "segmentation_model";
constexpr std::array<std::string_view, 13> kKeys = {
    "name", "model", "input_width", "input_height", "layout",  "color_order",    "scale",
    "mean", "std",   "input",       "output",       "classes", "dynamic_classes"};

std::string label(const std::string& key) { return fmt::format("{}.{}", kRoot, key); }

YAML::Node required(const YAML::Node& node, const std::string& key,
                    const std::filesystem::path& file) {
  const YAML::Node value = node[key];
  if (!value) util::failAt(file, util::yamlLine(node), label(key) + " is missing");
  return value;
}

template <typename T>
void readOptional(const YAML::Node& node, const std::string& key, const std::filesystem::path& file,
                  T& value) {
  if (const YAML::Node entry = node[key]) value = util::yamlValue<T>(entry, label(key), file);
}

cv::Scalar readTriple(const YAML::Node& node, const std::string& key,
                      const std::filesystem::path& file, cv::Scalar fallback) {
  const YAML::Node entry = node[key];
  if (!entry) return fallback;
  if (!entry.IsSequence() || entry.size() != 3) {
    util::failAt(file, util::yamlLine(entry), label(key) + " must be a list of 3 numbers");
  }
  cv::Scalar value;
  for (std::size_t c = 0; c < 3; ++c)
    value[c] = util::yamlValue<double>(entry[c], label(key), file);
  return value;
}

std::vector<std::string> readNames(const YAML::Node& node, const std::string& key,
                                   const std::filesystem::path& file) {
  const YAML::Node entry = required(node, key, file);
  if (!entry.IsSequence())
    util::failAt(file, util::yamlLine(entry), label(key) + " must be a list");
  std::vector<std::string> names;
  for (const auto& name : entry)
    names.push_back(util::yamlValue<std::string>(name, label(key), file));
  return names;
}

TensorLayout readLayout(const YAML::Node& node, const std::filesystem::path& file) {
  std::string layout = "nchw";
  readOptional(node, "layout", file, layout);
  if (layout == "nchw") return TensorLayout::kNchw;
  if (layout == "nhwc") return TensorLayout::kNhwc;
  util::failAt(file, util::yamlLine(node["layout"]),
               fmt::format("{} must be nchw or nhwc, not '{}'", label("layout"), layout));
}

bool readRgb(const YAML::Node& node, const std::filesystem::path& file) {
  std::string order = "rgb";
  readOptional(node, "color_order", file, order);
  if (order == "rgb" || order == "bgr") return order == "rgb";
  util::failAt(file, util::yamlLine(node["color_order"]),
               fmt::format("{} must be rgb or bgr, not '{}'", label("color_order"), order));
}

void validate(const ModelConfig& config, const YAML::Node& node,
              const std::filesystem::path& file) {
  if (config.input_size.width <= 0 || config.input_size.height <= 0) {
    util::failAt(file, util::yamlLine(node["input_width"]), "input size must be positive");
  }
  for (int c = 0; c < 3; ++c) {
    if (config.std[c] <= 0.0) {
      util::failAt(file, util::yamlLine(node["std"]), label("std") + " must be positive");
    }
  }
  if (config.classes.empty() || config.classes.size() > 255) {
    util::failAt(file, util::yamlLine(node["classes"]),
                 label("classes") + " must list 1-255 names");
  }
  for (std::size_t i = 0; i < config.dynamic_classes.size(); ++i) {
    const auto& name = config.dynamic_classes[i];
    if (std::find(config.classes.begin(), config.classes.end(), name) == config.classes.end()) {
      util::failAt(file, util::yamlLine(node["dynamic_classes"][i]),
                   fmt::format("dynamic class '{}' is not one of {}", name, label("classes")));
    }
  }
}

}  // namespace

std::vector<int> ModelConfig::dynamicClassIndices() const {
  std::vector<int> indices;
  for (const auto& name : dynamic_classes) {
    const auto it = std::find(classes.begin(), classes.end(), name);
    if (it != classes.end()) indices.push_back(static_cast<int>(it - classes.begin()));
  }
  return indices;
}

ModelConfig readModelConfig(const std::filesystem::path& file) {
  return parseModelConfig(util::readTextFile(file), file);
}

ModelConfig parseModelConfig(std::string_view text, const std::filesystem::path& file) {
  const YAML::Node root = util::parseYaml(text, file);
  if (!root.IsMap() || !root[std::string(kRoot)] || !root[std::string(kRoot)].IsMap()) {
    util::failAt(file, util::yamlLine(root),
                 fmt::format("expected a top-level '{}:' mapping", kRoot));
  }
  const YAML::Node node = root[std::string(kRoot)];
  util::rejectUnknownYamlKeys(node, kKeys, std::string(kRoot) + ".", file);
  ModelConfig config;
  config.name = util::yamlValue<std::string>(required(node, "name", file), label("name"), file);
  config.model = util::yamlValue<std::string>(required(node, "model", file), label("model"), file);
  config.input_size.width =
      util::yamlValue<int>(required(node, "input_width", file), label("input_width"), file);
  config.input_size.height =
      util::yamlValue<int>(required(node, "input_height", file), label("input_height"), file);
  config.layout = readLayout(node, file);
  config.rgb = readRgb(node, file);
  readOptional(node, "scale", file, config.scale);
  config.mean = readTriple(node, "mean", file, config.mean);
  config.std = readTriple(node, "std", file, config.std);
  readOptional(node, "input", file, config.input);
  readOptional(node, "output", file, config.output);
  config.classes = readNames(node, "classes", file);
  config.dynamic_classes = readNames(node, "dynamic_classes", file);
  validate(config, node, file);
  return config;
}

std::filesystem::path resolveModelFile(const ModelConfig& config,
                                       const std::filesystem::path& config_file,
                                       const std::optional<std::filesystem::path>& override_file) {
  return util::findModelFile(config.model, config_file, override_file, "segmentation model");
}

}  // namespace segslam::segmentation
