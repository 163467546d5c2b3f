#include "segslam/synth/scene_builder.h"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace segslam::synth {

namespace {

// A seed for one stream of randomness: texture i, or the layout (index 0xffffffff).
std::uint64_t streamSeed(std::uint32_t scene_seed, std::size_t index) {
  std::seed_seq sequence{scene_seed, static_cast<std::uint32_t>(index), 0x7e47u};
  std::array<std::uint32_t, 2> words{};
  sequence.generate(words.begin(), words.end());
  return (static_cast<std::uint64_t>(words[0]) << 32) | words[1];
}

int texelsFor(double metres) {
  return std::max(1, static_cast<int>(std::ceil(metres / kTexelSize)) + 1);
}

}  // namespace

SceneBuilder::SceneBuilder(std::uint32_t seed) : seed_(seed), rng_(streamSeed(seed, 0xffffffffu)) {}

std::uint16_t SceneBuilder::beginObject(core::SemanticClass semantic_class, std::string name,
                                        bool movable) {
  if (objects_.size() >= 0xffff) throw std::length_error("SceneBuilder: too many objects");
  const auto instance = static_cast<std::uint16_t>(objects_.size() + 1);
  objects_.push_back({{instance, semantic_class, std::move(name), movable}, {}});
  return instance;
}

void SceneBuilder::addRect(const Rect& rect, Material material) {
  if (objects_.empty()) throw std::logic_error("SceneBuilder::addRect before beginObject");
  BuiltObject& object = objects_.back();
  const Texture* texture = makeTexture(material, {rect.size_u, rect.size_v});
  object.rects.push_back(
      {rect, {texture, object.info.instance, object.info.semantic_class, false}});
}

void SceneBuilder::addBox(const Eigen::Vector3d& low, const Eigen::Vector3d& high,
                          Material material) {
  for (const Rect& face : boxFaces(low, high)) addRect(face, material);
}

void SceneBuilder::placeCurrentObject(const geometry::Pose& placement) {
  if (objects_.empty())
    throw std::logic_error("SceneBuilder::placeCurrentObject before beginObject");
  for (auto& rect : objects_.back().rects) rect.shape = transformed(placement, rect.shape);
}

const Texture* SceneBuilder::makeTexture(Material material, const Eigen::Vector2d& extent) {
  requests_.push_back({material, cv::Size(texelsFor(extent.x()), texelsFor(extent.y())),
                       streamSeed(seed_, textures_.size())});
  textures_.push_back(
      std::make_unique<Texture>(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(0)), kTexelSize));
  return textures_.back().get();
}

void SceneBuilder::finish() {
  const std::size_t first = textures_.size() - requests_.size();
  tbb::parallel_for(std::size_t{0}, requests_.size(), [&](std::size_t i) {
    const TextureRequest& request = requests_[i];
    *textures_[first + i] =
        Texture(paintTexture(request.material, request.size, kTexelSize, request.seed), kTexelSize);
  });
  requests_.clear();
}

}  // namespace segslam::synth
