#include "segslam/place/cnn_backbone_config.h"

#include <fmt/format.h>

#include <array>
#include <set>

#include "segslam/util/error.h"
#include "segslam/util/model_file.h"
#include "segslam/util/text_file.h"
#include "segslam/util/yaml_document.h"

namespace segslam::place {

namespace {

constexpr std::string_view kRoot = "cnn_backbone";
constexpr std::array<std::string_view, 11> kKeys = {
    "name", "model", "input_width", "input_height", "color_order", "scale",
    "mean", "std",   "stored_grid", "pooling_grid", "layers"};
constexpr std::array<std::string_view, 3> kLayerKeys = {"name", "layer", "erosion_px"};

std::string label(const std::string& key) { return fmt::format("{}.{}", kRoot, key); }

YAML::Node required(const YAML::Node& node, const std::string& key, const std::string& what,
                    const std::filesystem::path& file) {
  const YAML::Node value = node[key];
  if (!value) util::failAt(file, util::yamlLine(node), what + " is missing");
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

cv::Size readGrid(const YAML::Node& node, const std::string& key, const std::filesystem::path& file,
                  cv::Size fallback) {
  const YAML::Node entry = node[key];
  if (!entry) return fallback;
  if (!entry.IsSequence() || entry.size() != 2) {
    util::failAt(file, util::yamlLine(entry), label(key) + " must be [width, height]");
  }
  const cv::Size grid(util::yamlValue<int>(entry[0], label(key), file),
                      util::yamlValue<int>(entry[1], label(key), file));
  if (grid.width <= 0 || grid.height <= 0) {
    util::failAt(file, util::yamlLine(entry), label(key) + " must be positive");
  }
  return grid;
}

bool readRgb(const YAML::Node& node, const std::filesystem::path& file) {
  std::string order = "rgb";
  readOptional(node, "color_order", file, order);
  if (order == "rgb" || order == "bgr") return order == "rgb";
  util::failAt(file, util::yamlLine(node["color_order"]),
               fmt::format("{} must be rgb or bgr, not '{}'", label("color_order"), order));
}

CnnLayer readLayer(const YAML::Node& node, const std::filesystem::path& file) {
  const std::string what = label("layers") + " entry";
  if (!node.IsMap()) {
    util::failAt(file, util::yamlLine(node), what + " must be a mapping {name, layer}");
  }
  util::rejectUnknownYamlKeys(node, kLayerKeys, label("layers") + ".", file);
  CnnLayer layer;
  layer.name = util::yamlValue<std::string>(required(node, "name", what + " name", file),
                                            what + " name", file);
  layer.layer = util::yamlValue<std::string>(required(node, "layer", what + " layer", file),
                                             what + " layer", file);
  if (const YAML::Node erosion = node["erosion_px"]) {
    layer.erosion_px = util::yamlValue<int>(erosion, what + " erosion_px", file);
    if (layer.erosion_px < 0) {
      util::failAt(file, util::yamlLine(erosion), what + " erosion_px must not be negative");
    }
  }
  return layer;
}

std::vector<CnnLayer> readLayers(const YAML::Node& node, const std::filesystem::path& file) {
  const YAML::Node entry = required(node, "layers", label("layers"), file);
  if (!entry.IsSequence() || entry.size() == 0) {
    util::failAt(file, util::yamlLine(entry), label("layers") + " must be a non-empty list");
  }
  std::vector<CnnLayer> layers;
  std::set<std::string> names;
  for (const auto& item : entry) {
    layers.push_back(readLayer(item, file));
    if (!names.insert(layers.back().name).second) {
      util::failAt(file, util::yamlLine(item),
                   fmt::format("layer name '{}' appears twice", layers.back().name));
    }
  }
  return layers;
}

void validate(const CnnBackboneConfig& config, const YAML::Node& node,
              const std::filesystem::path& file) {
  if (config.input_size.width <= 0 || config.input_size.height <= 0) {
    util::failAt(file, util::yamlLine(node["input_width"]), "input size must be positive");
  }
  for (int c = 0; c < 3; ++c) {
    if (config.std[c] <= 0.0) {
      util::failAt(file, util::yamlLine(node["std"]), label("std") + " must be positive");
    }
  }
  if (config.pooling_grid.width > config.stored_grid.width ||
      config.pooling_grid.height > config.stored_grid.height) {
    util::failAt(file, util::yamlLine(node["pooling_grid"]),
                 label("pooling_grid") + " must not be finer than " + label("stored_grid"));
  }
}

}  // namespace

CnnBackboneConfig readCnnBackboneConfig(const std::filesystem::path& file) {
  return parseCnnBackboneConfig(util::readTextFile(file), file);
}

CnnBackboneConfig parseCnnBackboneConfig(std::string_view text, const std::filesystem::path& file) {
  const YAML::Node root = util::parseYaml(text, file);
  if (!root.IsMap() || !root[std::string(kRoot)] || !root[std::string(kRoot)].IsMap()) {
    util::failAt(file, util::yamlLine(root),
                 fmt::format("expected a top-level '{}:' mapping", kRoot));
  }
  const YAML::Node node = root[std::string(kRoot)];
  util::rejectUnknownYamlKeys(node, kKeys, std::string(kRoot) + ".", file);
  CnnBackboneConfig config;
  config.name = util::yamlValue<std::string>(required(node, "name", label("name"), file),
                                             label("name"), file);
  config.model = util::yamlValue<std::string>(required(node, "model", label("model"), file),
                                              label("model"), file);
  config.input_size.width = util::yamlValue<int>(
      required(node, "input_width", label("input_width"), file), label("input_width"), file);
  config.input_size.height = util::yamlValue<int>(
      required(node, "input_height", label("input_height"), file), label("input_height"), file);
  config.rgb = readRgb(node, file);
  readOptional(node, "scale", file, config.scale);
  config.mean = readTriple(node, "mean", file, config.mean);
  config.std = readTriple(node, "std", file, config.std);
  config.stored_grid = readGrid(node, "stored_grid", file, config.stored_grid);
  config.pooling_grid = readGrid(node, "pooling_grid", file, config.pooling_grid);
  config.layers = readLayers(node, file);
  validate(config, node, file);
  return config;
}

std::filesystem::path resolveBackboneModelFile(
    const CnnBackboneConfig& config, const std::filesystem::path& config_file,
    const std::optional<std::filesystem::path>& override_file) {
  return util::findModelFile(config.model, config_file, override_file, "CNN backbone model",
                             "--backbone-model");
}

}  // namespace segslam::place
