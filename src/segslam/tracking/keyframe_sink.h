#pragma once

#include <memory>

#include "segslam/map/keyframe.h"

namespace segslam::tracking {

// Where tracking hands new keyframes: the local mapping queue.
class KeyFrameSink {
 public:
  virtual ~KeyFrameSink() = default;
  virtual void insertKeyFrame(std::shared_ptr<map::KeyFrame> keyframe) = 0;
  // True when mapping has caught up and can take a keyframe now.
  [[nodiscard]] virtual bool isIdle() const = 0;
  [[nodiscard]] virtual std::size_t queuedKeyFrames() const = 0;
};

}  // namespace segslam::tracking
