#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "segslam/synth/person.h"
#include "segslam/synth/primitives.h"
#include "segslam/synth/push_motion.h"
#include "segslam/synth/scene_object.h"
#include "segslam/synth/synth_options.h"
#include "segslam/synth/texture.h"

namespace segslam::synth {

class SceneBuilder;

// World position of a moving object's reference point at one frame: a person's base centre on
// the floor, a piece of furniture's placement origin (centre of its footprint, on the floor).
struct ObjectPosition {
  std::uint16_t instance = 0;
  core::SemanticClass semantic_class = core::SemanticClass::kNone;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// The textured room with its furniture and people over the frames of a sequence (frame k is at
// time k / fps seconds).
//
// Dynamic objects: an object is dynamic at frame k when its world pose at k differs from its pose
// at k - 1 or at k + 1 (frames outside the sequence do not count). For a person the pose includes
// the swing of the limbs, so a walking person is dynamic at every frame and a person standing
// still (speed 0) never is; the pushed chair is dynamic only during its push. Dynamic objects are
// exactly what the ground-truth masks show.
class Scene {
 public:
  // `options` must be valid (see validateOptions).
  explicit Scene(const SynthOptions& options);

  [[nodiscard]] const std::vector<SceneObject>& objects() const { return objects_; }
  [[nodiscard]] int frameCount() const { return frames_; }

  // Every surface at frame k in world coordinates, marked dynamic as defined above.
  [[nodiscard]] RenderScene renderSceneAt(int frame) const;

  [[nodiscard]] bool isDynamic(std::uint16_t instance, int frame) const;
  // The dynamic objects at frame k, in instance order.
  [[nodiscard]] std::vector<ObjectPosition> dynamicObjectsAt(int frame) const;

 private:
  struct MovingFurniture {
    std::uint16_t instance = 0;
    std::vector<TexturedRect> rects;  // object frame
    PushMotion motion;
  };
  struct Walker {
    std::uint16_t instance = 0;
    Person person;
    std::array<const Texture*, kBodyMaterialCount> textures{};
  };

  void addPeople(const SynthOptions& options, SceneBuilder& builder);
  [[nodiscard]] static double timeOf(int frame);
  template <typename PoseAt>
  [[nodiscard]] bool changesAround(int frame, const PoseAt& pose_at) const;
  [[nodiscard]] bool furnitureIsDynamic(const MovingFurniture& furniture, int frame) const;
  [[nodiscard]] bool walkerIsDynamic(const Walker& walker, int frame) const;

  int frames_ = 0;
  std::vector<std::unique_ptr<Texture>> textures_;
  std::vector<SceneObject> objects_;  // objects_[i].instance == i + 1
  std::vector<TexturedRect> static_rects_;
  std::vector<MovingFurniture> furniture_;
  std::vector<Walker> walkers_;
};

}  // namespace segslam::synth
