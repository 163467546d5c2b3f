#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "segslam/synth/primitives.h"
#include "segslam/synth/scene_object.h"
#include "segslam/synth/texture.h"
#include "segslam/synth/texture_painter.h"

namespace segslam::synth {

// An object as built: its description and its surfaces in its own frame (for objects that never
// move, the world frame).
struct BuiltObject {
  SceneObject info;
  std::vector<TexturedRect> rects;
};

// Collects the objects of a scene and the textures of their surfaces. Every surface gets its own
// procedural texture; all randomness comes from the seed, in the order of the calls. Textures are
// painted together (in parallel) by finish(); the pointers handed out before stay valid.
class SceneBuilder {
 public:
  explicit SceneBuilder(std::uint32_t seed);

  // Starts the next object (instance ids count up from 1); add* calls add to it.
  std::uint16_t beginObject(core::SemanticClass semantic_class, std::string name,
                            bool movable = false);
  void addRect(const Rect& rect, Material material);
  // The six outward faces of the axis-aligned box [low, high] of the current object's frame.
  void addBox(const Eigen::Vector3d& low, const Eigen::Vector3d& high, Material material);

  // Moves everything added to the current object so far by `placement` (object to world).
  void placeCurrentObject(const geometry::Pose& placement);

  // A texture of `material` covering `extent` (metres) of a surface, painted by finish().
  const Texture* makeTexture(Material material, const Eigen::Vector2d& extent);

  // Randomness for the layout itself (sizes, colours, phases), seeded from the scene seed.
  std::mt19937_64& rng() { return rng_; }

  // Paints every texture requested since the last call.
  void finish();

  std::vector<std::unique_ptr<Texture>> takeTextures() { return std::move(textures_); }
  std::vector<BuiltObject> takeObjects() { return std::move(objects_); }

 private:
  struct TextureRequest {
    Material material;
    cv::Size size;
    std::uint64_t seed;
  };

  std::uint32_t seed_;
  std::mt19937_64 rng_;
  std::vector<std::unique_ptr<Texture>> textures_;
  std::vector<TextureRequest> requests_;
  std::vector<BuiltObject> objects_;
};

}  // namespace segslam::synth
