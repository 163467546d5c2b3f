#include "segslam/dense/keyframe_fold.h"

#include <limits>

namespace segslam::dense {

std::size_t nearestView(const Eigen::Isometry3d& culled,
                        const std::vector<Eigen::Isometry3d>& candidates) {
  std::size_t best = 0;
  double best_score = std::numeric_limits<double>::max();
  const Eigen::Vector3d axis = culled.linear().col(2);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const double distance = (candidates[k].translation() - culled.translation()).norm();
    const double turn = 1.0 - axis.dot(candidates[k].linear().col(2));
    const double score = distance + 0.5 * turn;
    if (score < best_score) {
      best_score = score;
      best = k;
    }
  }
  return best;
}

KeyFrameCloud foldInto(const KeyFrameCloud& into, const Eigen::Isometry3d& T_w_into,
                       const KeyFrameCloud& from, const Eigen::Isometry3d& T_w_from,
                       double voxel_size) {
  const Eigen::Isometry3d T_into_from = T_w_into.inverse() * T_w_from;
  KeyFrameCloud folded = into;
  folded.static_points.append(transformed(from.static_points, T_into_from));
  folded.dynamic_points.append(transformed(from.dynamic_points, T_into_from));
  return {voxelDownsample(folded.static_points, voxel_size),
          voxelDownsample(folded.dynamic_points, voxel_size)};
}

}  // namespace segslam::dense
