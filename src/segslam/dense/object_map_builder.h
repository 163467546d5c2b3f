#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/dense/dynamic_object_tracker.h"
#include "segslam/dense/labelled_cloud.h"
#include "segslam/dense/object_association.h"
#include "segslam/dense/object_map.h"

namespace segslam::dense {

struct ObjectMapOptions {
  // Edge of the cells in which keyframes' segments are compared (metres): two map voxels, so
  // that views of one surface a depth-noise apart still share cells.
  double cell_size = 0.02;
  // A keyframe's segment of fewer points (1 cm voxels) is a stray label, not an object's view.
  std::size_t min_segment_points = 50;
  ObjectAssociationOptions association;
  // A static object is real when at least this many keyframes saw it and at least this share of
  // the keyframes whose view holds its centroid did: a label that flickers on in a view or two
  // is not an object, while a table the network names in one view of eight is.
  int min_keyframes = 3;
  double min_seen_share = 0.1;
  // Objects with fewer points in the final map are left out.
  std::size_t min_points = 100;
  // A dynamic track is an object when it holds at least this share of the dynamic layer's points
  // in the keyframes that saw it: the mask is made for the moving object, while a label that
  // covers a sliver of it where the mask spills over the edge of a monitor is not one.
  double min_dynamic_share = 0.15;
  // A track is a moving object when it got this far from where it was first seen (m). One that
  // did not is a person who sat still (an object, not a moving one, when seen in min_keyframes
  // keyframes) or a mask that stayed on a static thing (no object: the static objects hold it).
  double min_travel = 0.5;
  // A moving track of a label other than person with this share of its points or more within
  // one cell (cell_size) of the static map's is a mask that slid over a static thing, not a
  // moving object: a monitor a walker passed, its centroid moving with the mask's edge.
  double max_on_static_share = 0.9;
  DynamicTrackingOptions dynamic;
};

// Builds the map's objects from the keyframes, in their final poses: each keyframe's labelled
// segments are associated with the objects of the keyframes before it (ObjectAssociator) and
// the dynamic layer's with tracks (DynamicObjectTracker). Static objects then take their points
// from the final static map: every object-labelled point goes to the object of its label that saw
// its cell in the most keyframes (of any label when none of its label did). Rebuilt from scratch
// whenever the map is (after a loop correction too).
class ObjectMapBuilder {
 public:
  // `max_depth`: the range of the depth the map is made of, for which keyframes see a point.
  ObjectMapBuilder(const core::Camera& camera, double max_depth, ObjectMapOptions options);

  // Keyframes in time order: their pose (camera to world) and both layers in the world frame.
  void addKeyFrame(std::uint64_t id, double timestamp, const Eigen::Isometry3d& T_wc,
                   const LabelledCloud& static_points, const LabelledCloud& dynamic_points);

  // The objects, numbered (numberObjects), with the points of `static_map` and the dynamic
  // tracks voxelised with `voxel_size`.
  [[nodiscard]] std::vector<MapObject> objects(const LabelledCloud& static_map,
                                               double voxel_size) const;

 private:
  [[nodiscard]] int keyframesSeeing(const Eigen::Vector3f& point) const;
  [[nodiscard]] std::vector<MapObject> staticObjects(const LabelledCloud& static_map) const;
  // The dynamic layer's tracks that are objects: the moving ones, and people who sat still.
  [[nodiscard]] std::vector<MapObject> dynamicObjects(const LabelledCloud& static_map,
                                                      double voxel_size) const;
  // The share of `points` within one cell (cell_size) of a cell of `static_cells`.
  [[nodiscard]] double shareOnStatic(const LabelledCloud& points,
                                     const std::unordered_set<std::uint64_t>& static_cells) const;

  core::Camera camera_;
  double max_depth_;
  ObjectMapOptions options_;
  ObjectAssociator associator_;
  DynamicObjectTracker tracker_;
  std::vector<Eigen::Isometry3d> T_cw_;  // world to camera of every keyframe
};

}  // namespace segslam::dense
