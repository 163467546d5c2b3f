#include "segslam/mapping/keyframe_mask.h"

#include "segslam/feature/static_mask.h"

namespace segslam::mapping {

OwnMaskOutcome applyOwnMask(map::KeyFrame& keyframe, const cv::Mat& dilated_mask,
                            const OwnMaskOptions& options) {
  OwnMaskOutcome outcome;
  if (dilated_mask.empty()) return outcome;
  for (const auto& [index, point] : keyframe.validMapPoints()) {
    if (!feature::isDynamicAt(dilated_mask, keyframe.keypoints[index].pt)) continue;
    if (point->first_keyframe_id == keyframe.id ||
        ++point->moving_votes >= options.moving_votes_to_cull) {
      point->setBad();
      ++outcome.points_culled;
      continue;
    }
    keyframe.eraseMapPoint(index);
    point->eraseObservation(&keyframe);
    ++outcome.observations_dropped;
  }
  keyframe.dynamic_mask = keyframe.dynamic_mask.united(dilated_mask);
  return outcome;
}

}  // namespace segslam::mapping
