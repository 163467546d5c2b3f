#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>

#include "segslam/feature/scale_levels.h"

namespace segslam::map {

class KeyFrame;

// Orders keyframes by id so that every iteration over observations is deterministic.
struct KeyFrameIdLess {
  bool operator()(const KeyFrame* a, const KeyFrame* b) const;
};

// A 3D point of the static world, observed by keyframes. All members are guarded by the owning
// Map's mutex.
class MapPoint {
 public:
  MapPoint(std::uint64_t id, const Eigen::Vector3d& position, KeyFrame* reference_keyframe);

  void addObservation(KeyFrame* keyframe, std::size_t keypoint_index);
  void eraseObservation(KeyFrame* keyframe);
  [[nodiscard]] const std::map<KeyFrame*, std::size_t, KeyFrameIdLess>& observations() const {
    return observations_;
  }
  [[nodiscard]] int numObservations() const;
  [[nodiscard]] bool isObservedBy(const KeyFrame* keyframe) const;

  // Picks the observed descriptor with the least median distance to the others, the
  // representative used for matching.
  void updateDescriptor();
  // Mean viewing direction and the distance range over which the point can be matched, from
  // the reference keyframe's observation and the pyramid's scale.
  void updateNormalAndDepth();
  // Pyramid level at which a camera at `distance` should see this point.
  [[nodiscard]] int predictLevel(double distance, const feature::ScaleLevels& levels) const;

  void increaseVisible(int n = 1) { visible_ += n; }
  void increaseFound(int n = 1) { found_ += n; }
  [[nodiscard]] double foundRatio() const { return static_cast<double>(found_) / visible_; }

  // Removes the point from every keyframe and marks it bad.
  void setBad();
  // Moves all observations to `other` (which survives) and marks this point bad.
  void replaceWith(const std::shared_ptr<MapPoint>& other);

  std::uint64_t id;
  std::uint64_t first_keyframe_id;
  Eigen::Vector3d position;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  cv::Mat descriptor;  // 1 x 32, CV_8U
  double min_distance = 0.0;
  double max_distance = 0.0;
  KeyFrame* reference_keyframe;
  bool bad = false;
  // Restored from a map file: an earlier session's point, which a later session culls only on
  // evidence that it is gone (seen through, on a moving object), not for losing the keyframes
  // that saw it, nor for being merged with a new point (the restored point survives the merge).
  bool restored = false;
  std::shared_ptr<MapPoint> replaced_by;
  // Tracking bookkeeping: which local-map search (Tracker::trackLocalMap) last found this point /
  // took it into the local map.
  std::uint64_t seen_in_search = UINT64_MAX;
  std::uint64_t local_map_search = UINT64_MAX;
  // Frames whose depth saw through the point (tracking::pointsSeenThrough).
  int seen_through = 0;
  // Keyframes whose own segmentation showed the point on a moving object
  // (mapping::applyOwnMask).
  int moving_votes = 0;
  // Not yet checked by local mapping: made by a keyframe that local mapping has not taken up
  // (it may wait for the keyframe's own mask), or a temporary point of tracking. Tracking lets
  // such points refine a pose but not decide it (a person whom the masks missed can carry
  // hundreds of them).
  bool provisional = false;

 private:
  std::map<KeyFrame*, std::size_t, KeyFrameIdLess> observations_;
  int visible_ = 1;
  int found_ = 1;
};

}  // namespace segslam::map
