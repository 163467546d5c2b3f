#include "segslam/segmentation/semantic_class_map.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <stdexcept>
#include <utility>

namespace segslam::segmentation {

namespace {

using core::SemanticClass;

constexpr std::array<std::pair<std::string_view, SemanticClass>, 6> kAliases = {{
    {"tvmonitor", SemanticClass::kMonitor},
    {"tv", SemanticClass::kMonitor},
    {"diningtable", SemanticClass::kTable},
    {"pottedplant", SemanticClass::kPlant},
    {"couch", SemanticClass::kSofa},
    {"people", SemanticClass::kPerson},
}};

// Lower case without spaces, underscores or dashes: "dining table", "potted_plant" and
// "TV-monitor" match the aliases too.
std::string canonicalName(std::string_view name) {
  std::string canonical;
  for (char c : name) {
    if (c == ' ' || c == '_' || c == '-') continue;
    canonical += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return canonical;
}

}  // namespace

SemanticClass semanticClassOfModelClass(std::string_view name) {
  const std::string canonical = canonicalName(name);
  for (const auto& [alias, semantic_class] : kAliases) {
    if (canonical == alias) return semantic_class;
  }
  const auto known = core::semanticClassFromName(canonical);
  return known.value_or(SemanticClass::kNone);
}

SemanticClassMap::SemanticClassMap(const std::vector<std::string>& model_classes)
    : table_(1, 256, CV_8UC1, cv::Scalar(0)) {
  const std::size_t n = std::min<std::size_t>(model_classes.size(), 256);
  for (std::size_t i = 0; i < n; ++i) {
    table_.at<std::uint8_t>(0, static_cast<int>(i)) =
        static_cast<std::uint8_t>(semanticClassOfModelClass(model_classes[i]));
  }
}

cv::Mat SemanticClassMap::apply(const cv::Mat& model_labels) const {
  if (model_labels.empty()) return {};
  if (model_labels.type() != CV_8UC1) {
    throw std::invalid_argument("SemanticClassMap: labels must be CV_8UC1");
  }
  cv::Mat labels;
  cv::LUT(model_labels, table_, labels);
  return labels;
}

SemanticClass SemanticClassMap::classOf(int model_index) const {
  if (model_index < 0 || model_index > 255) return SemanticClass::kNone;
  return static_cast<SemanticClass>(table_.at<std::uint8_t>(0, model_index));
}

}  // namespace segslam::segmentation
