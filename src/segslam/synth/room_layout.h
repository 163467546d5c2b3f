#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "segslam/synth/person.h"
#include "segslam/synth/push_motion.h"
#include "segslam/synth/scene_builder.h"

namespace segslam::synth {

// The furnished room every synthetic sequence plays in (metres, z up, floor at z = 0):
// x in [0, 5.2], y in [0, 5], z in [0, 2.7]. The cameras stand near x = 1 and look mostly
// towards +x: at a table with a monitor and two chairs in the middle, a cabinet and a bookshelf
// against the far wall (x = 5.2), a sideboard on the left (y = 5) and a low shelf on the right
// (y = 0), boxes here and there.
Eigen::AlignedBox3d roomBox();

// Lanes that people walk back and forth along, one per person, in the part of the room the
// cameras look at; they avoid the furniture and each other.
std::vector<WalkLane> walkLanes();

// How chair_1 is pushed when furniture moves: 0.55 m towards and under the table, turning by
// 12 degrees, during [0.3, 0.55] of the sequence duration (seconds).
PushMotion chairPush(double duration);

// Adds the walls, floor, ceiling and furniture to `builder`; returns chair_1's instance id. With
// `chair_moves`, chair_1 is kept in its own frame and marked movable (place it with chairPush);
// otherwise it stands where the push would start.
std::uint16_t buildRoom(SceneBuilder& builder, bool chair_moves);

}  // namespace segslam::synth
