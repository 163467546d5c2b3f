#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "segslam/core/trajectory.h"

namespace segslam::eval {

// When two ground-truth poses count as the same place.
struct LoopThresholds {
  double max_translation_m = 0.3;
  double max_rotation_deg = 20.0;
  // Pairs closer in time than this are neither loops nor non-loops: consecutive views of one
  // place would make loop detection trivial.
  double min_gap_s = 5.0;
};

// A pair of images (indices into the pose list, i < j) and whether it is a true loop.
struct LoopPair {
  std::size_t i = 0;
  std::size_t j = 0;
  double translation_m = 0.0;  // |t| of T_i^-1 T_j
  double rotation_deg = 0.0;   // acos((tr(R) - 1) / 2) of T_i^-1 T_j
  bool loop = false;
};

// Every pair at least min_gap_s apart, with its loop label: both the translation and the
// rotation of the relative transform below their thresholds.
std::vector<LoopPair> loopPairs(std::span<const core::StampedPose> poses,
                                const LoopThresholds& thresholds);

}  // namespace segslam::eval
