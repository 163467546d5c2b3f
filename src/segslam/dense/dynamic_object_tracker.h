#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "segslam/dense/keyframe_depth_view.h"
#include "segslam/dense/label_segments.h"
#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

struct DynamicTrackingOptions {
  // Cells of the dynamic layer's segments (metres): coarser than the static objects', so that a
  // person whose arm is cut off by a mask's edge stays one segment.
  double cell_size = 0.05;
  // A segment continues a track of its label when its centroid lies within
  // max_speed * (time since the track was last seen) + slack of the track's last centroid; of
  // the tracks in reach, the one it is nearest to relative to that reach.
  double max_speed = 2.0;  // m/s: a walking person
  double slack = 0.5;      // m: half a body, for a centroid that moves as the view changes
  // A track not seen for longer ends. Shorter absences are a person who left the view and came
  // back: the same track when they could have walked there.
  double max_gap = 60.0;  // s
  // A segment of fewer points is a stray label (a network's false person on a cup) or a sliver
  // at the image's border: it joins a tracked segment it touches, and neither starts a track nor
  // places one. Strays linked as people dragged a seated person's track across the room.
  std::size_t min_track_points = 300;
  // A track that has not moved (travelled within slack) is continued only within slack of where
  // it was seen, not across the reach of its absence, unless by a segment of at least this many
  // points in a keyframe that shows the track's place left (KeyFrameDepthView): a stray label, a
  // walker's partial view far away, or a walker passing in front of a seated person made the
  // seated person's track travel. A segment this large is also a person seen whole enough to be
  // someone else than a tracked segment beside it (nearbyTrack).
  std::size_t min_reach_points = 1000;
};

// One moving object across the keyframes that saw it.
struct DynamicTrack {
  std::uint8_t label = 0;
  std::uint16_t instance = 0;  // the segmentation's instance id, 0 = tracked here
  std::vector<std::uint64_t> keyframes;
  LabelledCloud points;             // world frame, every keyframe's segment
  std::size_t keyframe_points = 0;  // dynamic points of the keyframes that saw it, all labels
  Eigen::Vector3f first_centroid = Eigen::Vector3f::Zero();
  Eigen::Vector3f last_centroid = Eigen::Vector3f::Zero();
  double last_seen = 0.0;
  // The farthest a keyframe saw it from where it was first seen (m).
  float travelled = 0.0f;
  // A keyframe since it was last seen showed the place where it was empty (KeyFrameDepthView).
  bool place_left = false;
  // A keyframe once showed a place where it was seen empty: it moved, however little its partial
  // views' centroids did.
  bool left_a_place = false;
  // Seen again after a keyframe showed its place empty: a walker, however little the centroids
  // of their partial views moved (a walker near the camera, seen in parts, was taken for a
  // seated person and got a second track).
  bool came_back = false;
  // A keyframe before it was seen showed one of the places that placed it (a segment linked to it,
  // not one joining it by touching) empty: it walked there.
  bool arrived = false;
};

// Follows the dynamic layer's objects over the keyframes, so that one walking person is one
// object however far they walk. Segments with an instance id (a segmentation that tracks
// instances, or a dataset's ground truth) follow that id; the others are linked to the track of
// their label whose last centroid is nearest within reach, each track taking one segment per
// keyframe; another segment whose bounds come within `slack` of a tracked one of the keyframe
// (larger segments first) joins that track: a person split in two by a table edge. Not when it
// is person-sized and the room is seen between the two: then it is a second person beside them.
class DynamicObjectTracker {
 public:
  explicit DynamicObjectTracker(DynamicTrackingOptions options);

  // Keyframes in time order; `segments` from segmentByLabel of `points` (world frame) with
  // options().cell_size; `view` the keyframe's view of both layers with these segments.
  void addKeyFrame(std::uint64_t keyframe_id, double timestamp, const LabelledCloud& points,
                   const std::vector<LabelSegment>& segments, KeyFrameDepthView view);

  [[nodiscard]] const std::vector<DynamicTrack>& tracks() const { return tracks_; }
  [[nodiscard]] const DynamicTrackingOptions& options() const { return options_; }

 private:
  // Index of the track each untracked segment continues, one segment per track (none:
  // max size_t). `stayed` marks segments where something stood before (stoodThereBefore).
  [[nodiscard]] std::vector<std::size_t> link(double timestamp,
                                              const std::vector<LabelSegment>& segments,
                                              const std::vector<PlaceSight>& last_places,
                                              const std::vector<bool>& stayed) const;
  // The track of a segment of this keyframe (`track_of`, tracks_.size() and beyond = none yet)
  // whose bounds come within slack of `segment`'s, unless `segment` is of min_reach_points and
  // `view` shows the room between the two; tracks_.size() when none does.
  [[nodiscard]] std::size_t nearbyTrack(const std::vector<LabelSegment>& segments,
                                        const std::vector<std::size_t>& track_of,
                                        std::size_t segment, const KeyFrameDepthView& view) const;
  void extend(std::size_t track, std::uint64_t keyframe_id, double timestamp,
              const LabelledCloud& points, const LabelSegment& segment);

  // Whether a keyframe before this one showed `place` empty.
  [[nodiscard]] bool seenEmptyBefore(const Eigen::Vector3f& place) const;
  // Whether more keyframes before this one showed a static surface at `place` than showed it
  // empty: a static thing the mask now takes for a person, or someone there all along whom the
  // masks missed; not someone who walked there. One view of the wall behind a chair (its depth
  // missing at the chair's edge) must not make the chair a place someone walked to.
  [[nodiscard]] bool stoodThereBefore(const Eigen::Vector3f& place) const;

  DynamicTrackingOptions options_;
  std::vector<DynamicTrack> tracks_;
  std::vector<KeyFrameDepthView> earlier_views_;
};

}  // namespace segslam::dense
