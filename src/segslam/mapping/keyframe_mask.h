#pragma once

#include <opencv2/core.hpp>

#include "segslam/map/keyframe.h"

namespace segslam::mapping {

struct OwnMaskOptions {
  // An older map point that this many keyframes' own masks show on a moving object is culled;
  // one keyframe's mask may just overlap a static point at the object's outline.
  int moving_votes_to_cull = 2;
};

struct OwnMaskOutcome {
  int points_culled = 0;         // made by the keyframe on the object, or voted moving enough
  int observations_dropped = 0;  // older points the keyframe matched on the object
};

// A keyframe's own dynamic mask, known only after the keyframe was made (a segmentation
// network's output for its frame, while tracking had used a mask carried from an older one).
// Map points at the keyframe's keypoints that the mask marks lie on a moving object: those the
// keyframe made itself are culled at once; an older point matched there loses the keyframe's
// observation and gains a moving vote (MapPoint::moving_votes), and is culled once enough
// keyframes agree. The mask is added to the keyframe's own, which loop detection reads.
// `dilated_mask`: CV_8UC1 of the keyframe's image size, non-zero = dynamic, dilated as the
// frames' masks are. Caller holds the map mutex.
OwnMaskOutcome applyOwnMask(map::KeyFrame& keyframe, const cv::Mat& dilated_mask,
                            const OwnMaskOptions& options = {});

}  // namespace segslam::mapping
