#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "segslam/feature/run_length_mask.h"
#include "segslam/map/frame.h"
#include "segslam/map/map_point.h"

namespace segslam::map {

// A frame kept in the map. Besides the frame's features it holds the covisibility graph
// (keyframes sharing map points, weighted by how many) and the spanning tree used by loop
// correction. All members are guarded by the owning Map's mutex.
class KeyFrame : public std::enable_shared_from_this<KeyFrame> {
 public:
  KeyFrame(std::uint64_t id, const Frame& frame);

  [[nodiscard]] std::size_t size() const { return keypoints_un.size(); }
  [[nodiscard]] Eigen::Vector3d cameraCentre() const { return T_cw.inverse().translation(); }
  [[nodiscard]] Eigen::Vector3d unproject(std::size_t i) const;  // world point from depth
  [[nodiscard]] optim::RgbdObservation observation(std::size_t i) const;

  [[nodiscard]] const std::vector<std::shared_ptr<MapPoint>>& mapPoints() const {
    return map_points_;
  }
  void addMapPoint(const std::shared_ptr<MapPoint>& point, std::size_t index);
  void eraseMapPoint(std::size_t index);
  void eraseMapPoint(const MapPoint* point);
  // Valid (not bad) map points with their keypoint indices.
  [[nodiscard]] std::vector<std::pair<std::size_t, std::shared_ptr<MapPoint>>> validMapPoints()
      const;

  // Recomputes covisibility edges from the map points' observations (weight >= 15 shared
  // points, or the single best keyframe when none reaches 15) and attaches the keyframe to the
  // spanning tree, under its strongest older covisible keyframe, on the first call that finds
  // one.
  void updateConnections();
  void addConnection(KeyFrame* other, int weight);
  void eraseConnection(KeyFrame* other);
  [[nodiscard]] std::vector<KeyFrame*> bestCovisibles(std::size_t n) const;
  [[nodiscard]] std::vector<KeyFrame*> covisiblesWithWeight(int min_weight) const;
  [[nodiscard]] int weight(KeyFrame* other) const;
  // Attaches the keyframe under `tree_parent` as a saved map had it (map::restoreMap): later
  // updates keep that parent.
  void restoreParent(KeyFrame* tree_parent);

  // Removes the keyframe from the graph (children are re-attached to the tree) and from its
  // map points; the first keyframe is never removed.
  void setBad();
  // Frees what only a live keyframe needs (features, masks, image, grid, map point slots): a
  // culled keyframe stays in the map only as a node of the pose tree, for the frames that were
  // tracked relative to it. Only for a bad keyframe that no thread still reads outside the map
  // mutex (the loop closer's describe()).
  void releaseFeatures();
  [[nodiscard]] bool released() const { return released_; }

  std::uint64_t id;
  std::uint64_t frame_id;
  double timestamp;
  std::shared_ptr<const FrameCamera> camera;
  std::vector<cv::KeyPoint> keypoints;
  std::vector<cv::KeyPoint> keypoints_un;
  std::vector<float> depth;
  std::vector<float> right_u;
  cv::Mat descriptors;
  feature::RunLengthMask dynamic_mask;  // the frame's (dilated), with late masks added
  cv::Mat image;  // the frame's colour image until the loop closer has described the keyframe
  KeypointGrid grid;
  geometry::Pose T_cw;
  bool bad = false;
  KeyFrame* parent = nullptr;
  // Pose relative to the parent, frozen when the keyframe goes bad, so frames that used it as
  // their reference can still be placed after later optimisation of the parent.
  geometry::Pose T_c_parent = geometry::Pose::Identity();
  std::set<KeyFrame*, KeyFrameIdLess> children;

  // Bookkeeping of the local map and local BA (which search/keyframe last used this one).
  std::uint64_t local_map_search = UINT64_MAX;
  std::uint64_t ba_local_keyframe = UINT64_MAX;
  std::uint64_t ba_fixed_keyframe = UINT64_MAX;

 private:
  void sortConnections();
  void attachToOlderParent();

  std::vector<std::shared_ptr<MapPoint>> map_points_;
  std::map<KeyFrame*, int, KeyFrameIdLess> connections_;
  std::vector<KeyFrame*> ordered_connections_;  // by weight, descending
  std::vector<int> ordered_weights_;
  bool first_connection_ = true;
  bool released_ = false;
};

}  // namespace segslam::map
