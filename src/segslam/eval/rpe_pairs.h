#pragma once

#include <cstddef>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "segslam/core/trajectory.h"

namespace segslam::eval {

// Unit of the RPE delta, as TUM evaluate_rpe.py's --delta_unit.
enum class DeltaUnit {
  kSeconds,  // "s": timestamps
  kFrames,   // "f": pose index
  kMeters,   // "m": distance travelled along the estimate
  kDegrees,  // "deg": rotation accumulated along the estimate
  kRadians,  // "rad"
};

std::string_view deltaUnitName(DeltaUnit unit);
std::vector<std::string> deltaUnitNames();
std::optional<DeltaUnit> parseDeltaUnit(std::string_view name);

// Pose indices (i, j) into the estimate: RPE compares the motion from pose i to pose j.
using PosePair = std::pair<std::size_t, std::size_t>;

// Position of each estimated pose on the axis the delta is measured along: its timestamp, its
// index, or the distance / rotation angle accumulated over the motions between consecutive poses.
std::vector<double> deltaIndex(const core::Trajectory& estimate, DeltaUnit unit);

// For each pose i, the pair (i, j) with j the pose whose index is closest to index[i] + delta
// (the tool's binary search). Like the tool, pairs whose j is the last pose are dropped and j may
// equal i.
std::vector<PosePair> fixedDeltaPairs(std::span<const double> index, double delta);

// The tool's pairs without a fixed delta: all (i, j) of `pose_count` poses when max_pairs is 0 or
// pose_count < sqrt(max_pairs), otherwise max_pairs pairs drawn uniformly with replacement.
std::vector<PosePair> allOrRandomPairs(std::size_t pose_count, std::size_t max_pairs,
                                       std::mt19937_64& rng);

// At most max_pairs of the pairs (0: all), drawn without replacement, in their original order.
std::vector<PosePair> limitPairs(std::vector<PosePair> pairs, std::size_t max_pairs,
                                 std::mt19937_64& rng);

}  // namespace segslam::eval
