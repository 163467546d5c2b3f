#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace segslam::core {

// Per-pixel semantic labels written by `segslam synth` (8-bit label images) and used by the
// segmentation and map modules. Values are stable: they are stored in files.
enum class SemanticClass : std::uint8_t {
  kNone = 0,  // nothing rendered / unknown
  kWall = 1,
  kFloor = 2,
  kCeiling = 3,
  kTable = 4,
  kChair = 5,
  kCabinet = 6,
  kBox = 7,
  kPerson = 8,
  kMonitor = 9,
  kShelf = 10,
  // Indoor classes a segmentation network knows but the synthetic scenes do not render.
  kBottle = 11,
  kSofa = 12,
  kPlant = 13,
};

inline constexpr std::array<std::string_view, 14> kSemanticClassNames = {
    "none", "wall",   "floor",   "ceiling", "table",  "chair", "cabinet",
    "box",  "person", "monitor", "shelf",   "bottle", "sofa",  "plant"};

inline constexpr std::string_view semanticClassName(SemanticClass c) {
  const auto i = static_cast<std::size_t>(c);
  return i < kSemanticClassNames.size() ? kSemanticClassNames[i] : "invalid";
}

inline constexpr std::optional<SemanticClass> semanticClassFromName(std::string_view name) {
  for (std::size_t i = 0; i < kSemanticClassNames.size(); ++i) {
    if (kSemanticClassNames[i] == name) return static_cast<SemanticClass>(i);
  }
  return std::nullopt;
}

}  // namespace segslam::core
