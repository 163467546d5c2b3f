#pragma once

#include <cstdint>
#include <string>

#include "segslam/core/semantic_class.h"

namespace segslam::synth {

// One object of a synthetic scene. Every wall, the floor, the ceiling, each piece of furniture and
// each person is one object with its own instance id (1, 2, ...; 0 means "nothing").
struct SceneObject {
  std::uint16_t instance = 0;
  core::SemanticClass semantic_class = core::SemanticClass::kNone;
  std::string name;      // e.g. "wall_x0", "table", "chair_1", "person_2"
  bool movable = false;  // it changes its pose at some time of the sequence
};

}  // namespace segslam::synth
