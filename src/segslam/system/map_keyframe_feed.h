#pragma once

#include <cstdint>
#include <map>

#include "segslam/dense/map_builder.h"
#include "segslam/segmentation/mask_stream.h"

namespace segslam::system {

// Hands keyframes to the dense map builder once their own segmentation is known. Tracking makes a
// keyframe with a mask carried from an older network output, which may miss a person who has
// just come in; the network's output for the keyframe's own frame (FrameMaskSource::
// segmentKeyFrame) arrives a few frames later. A keyframe held here gets that output's mask
// added to its own and the output's labels in place of the carried ones; one whose output does
// not come within `max_wait_frames` frames goes to the map as it is.
class MapKeyFrameFeed {
 public:
  // `wait_for_own_masks`: off, keyframes go to the builder at once.
  MapKeyFrameFeed(dense::MapBuilder& builder, bool wait_for_own_masks,
                  std::uint64_t max_wait_frames = 90);

  void addKeyFrame(std::uint64_t frame_id, double timestamp, dense::KeyFrameImages images);
  // A keyframe's own output (LateOutput::keyframe; labels as core::SemanticClass ids).
  void addOwnMask(const segmentation::LateOutput& output);
  // Tracking has reached `frame_id`: keyframes that waited too long go as they are.
  void setTrackedFrame(std::uint64_t frame_id);
  // Every keyframe still held goes as it is.
  void flush();

 private:
  struct Held {
    double timestamp = 0.0;
    dense::KeyFrameImages images;
  };

  dense::MapBuilder& builder_;
  bool wait_for_own_masks_;
  std::uint64_t max_wait_frames_;
  std::map<std::uint64_t, Held> held_;  // by frame id
};

}  // namespace segslam::system
