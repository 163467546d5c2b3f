#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

namespace segslam::synth {

// Looks of the procedural surface textures. Every material mixes multi-scale noise with many
// sharp-edged marks (shapes, lines, checker patches, text) of varied size and colour, so that
// corner detectors such as ORB find features on every surface at every scale.
enum class Material {
  kWallpaper,
  kFloorPlanks,
  kCeilingTiles,
  kWood,
  kLaminate,
  kCardboard,
  kBook,
  kScreen,
  kFabric,
  kShirt,
  kTrousers,
  kSkin,
  kShoes,
};

// Texel size used for all textures: about 4.5 mm on the surface.
inline constexpr double kTexelSize = 0.0045;

// Paints a CV_8UC3 (BGR) texture of `size` texels, each `texel_size` metres wide, in the style of
// `material`. Equal arguments give identical images.
cv::Mat paintTexture(Material material, cv::Size size, double texel_size, std::uint64_t seed);

}  // namespace segslam::synth
