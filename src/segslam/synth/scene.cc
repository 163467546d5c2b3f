#include "segslam/synth/scene.h"

#include <algorithm>
#include <random>
#include <string>

#include "segslam/synth/room_layout.h"
#include "segslam/synth/scene_builder.h"

namespace segslam::synth {

namespace {

constexpr std::array<Material, kBodyMaterialCount> kBodyTextures{
    Material::kShirt, Material::kTrousers, Material::kSkin, Material::kShoes};

}  // namespace

Scene::Scene(const SynthOptions& options) : frames_(options.frames) {
  SceneBuilder builder(options.seed);
  const std::uint16_t chair = buildRoom(builder, options.moved_furniture);
  addPeople(options, builder);
  builder.finish();
  textures_ = builder.takeTextures();
  const double duration = timeOf(frames_ - 1);
  for (BuiltObject& object : builder.takeObjects()) {
    objects_.push_back(object.info);
    if (object.info.instance == chair && options.moved_furniture) {
      furniture_.push_back({chair, std::move(object.rects), chairPush(duration)});
    } else {
      static_rects_.insert(static_rects_.end(), object.rects.begin(), object.rects.end());
    }
  }
}

void Scene::addPeople(const SynthOptions& options, SceneBuilder& builder) {
  const auto lanes = walkLanes();
  for (int i = 0; i < options.people; ++i) {
    const std::uint16_t instance =
        builder.beginObject(core::SemanticClass::kPerson, "person_" + std::to_string(i + 1),
                            options.person_speed > 0.0);
    const double start_fraction = std::uniform_real_distribution<double>(0.0, 1.0)(builder.rng());
    Walker walker{
        instance,
        Person(lanes[i % lanes.size()], options.person_speed, options.person_size, start_fraction),
        {}};
    for (int m = 0; m < kBodyMaterialCount; ++m) {
      walker.textures[m] = builder.makeTexture(kBodyTextures[m], walker.person.textureExtent());
    }
    walkers_.push_back(std::move(walker));
  }
}

double Scene::timeOf(int frame) { return frame / kSynthFps; }

template <typename PoseAt>
bool Scene::changesAround(int frame, const PoseAt& pose_at) const {
  const auto here = pose_at(timeOf(frame));
  if (frame > 0 && !(pose_at(timeOf(frame - 1)) == here)) return true;
  return frame + 1 < frames_ && !(pose_at(timeOf(frame + 1)) == here);
}

bool Scene::furnitureIsDynamic(const MovingFurniture& furniture, int frame) const {
  return changesAround(frame, [&](double t) { return furniture.motion.at(t).matrix().eval(); });
}

bool Scene::walkerIsDynamic(const Walker& walker, int frame) const {
  return changesAround(frame, [&](double t) { return walker.person.poseAt(t); });
}

RenderScene Scene::renderSceneAt(int frame) const {
  const double t = timeOf(frame);
  RenderScene scene;
  scene.rects = static_rects_;
  for (const MovingFurniture& furniture : furniture_) {
    const geometry::Pose placement = furniture.motion.at(t);
    const bool dynamic = furnitureIsDynamic(furniture, frame);
    for (const TexturedRect& rect : furniture.rects) {
      SurfaceInfo surface = rect.surface;
      surface.dynamic = dynamic;
      scene.rects.push_back({transformed(placement, rect.shape), surface});
    }
  }
  for (const Walker& walker : walkers_) {
    const bool dynamic = walkerIsDynamic(walker, frame);
    for (const BodyPart& part : walker.person.body(walker.person.poseAt(t))) {
      const Texture* texture = walker.textures[static_cast<int>(part.material)];
      scene.ellipsoids.push_back(
          {part.shape, {texture, walker.instance, core::SemanticClass::kPerson, dynamic}});
    }
  }
  return scene;
}

bool Scene::isDynamic(std::uint16_t instance, int frame) const {
  for (const MovingFurniture& furniture : furniture_) {
    if (furniture.instance == instance) return furnitureIsDynamic(furniture, frame);
  }
  for (const Walker& walker : walkers_) {
    if (walker.instance == instance) return walkerIsDynamic(walker, frame);
  }
  return false;
}

std::vector<ObjectPosition> Scene::dynamicObjectsAt(int frame) const {
  const double t = timeOf(frame);
  std::vector<ObjectPosition> positions;
  for (const MovingFurniture& furniture : furniture_) {
    if (!furnitureIsDynamic(furniture, frame)) continue;
    positions.push_back({furniture.instance, objects_[furniture.instance - 1].semantic_class,
                         furniture.motion.at(t).translation()});
  }
  for (const Walker& walker : walkers_) {
    if (!walkerIsDynamic(walker, frame)) continue;
    const Eigen::Vector2d base = walker.person.poseAt(t).position;
    positions.push_back({walker.instance, core::SemanticClass::kPerson, {base.x(), base.y(), 0.0}});
  }
  std::sort(
      positions.begin(), positions.end(),
      [](const ObjectPosition& a, const ObjectPosition& b) { return a.instance < b.instance; });
  return positions;
}

}  // namespace segslam::synth
