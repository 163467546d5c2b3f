#include "segslam/eval/loop_ground_truth.h"

#include <numbers>

namespace segslam::eval {

std::vector<LoopPair> loopPairs(std::span<const core::StampedPose> poses,
                                const LoopThresholds& thresholds) {
  std::vector<LoopPair> pairs;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    for (std::size_t j = i + 1; j < poses.size(); ++j) {
      if (poses[j].timestamp - poses[i].timestamp < thresholds.min_gap_s) continue;
      const geometry::Pose relative = poses[i].T_wc.inverse() * poses[j].T_wc;
      LoopPair pair;
      pair.i = i;
      pair.j = j;
      pair.translation_m = relative.translation().norm();
      pair.rotation_deg = geometry::rotationAngle(relative) * 180.0 / std::numbers::pi;
      pair.loop = pair.translation_m < thresholds.max_translation_m &&
                  pair.rotation_deg < thresholds.max_rotation_deg;
      pairs.push_back(pair);
    }
  }
  return pairs;
}

}  // namespace segslam::eval
