#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "segslam/dense/label_segments.h"

namespace segslam::dense {

struct ObjectAssociationOptions {
  // A keyframe's segment is another view of an object when at least this share of the smaller
  // one's cells lie on or next to the other's.
  double min_overlap = 0.3;
  // A segment whose label is not the object's leading label joins it only when at least this
  // share of the segment lies on the object: a patch of a sofa labelled chair is the sofa seen
  // wrongly, while a table segment that merely borders a chair is not the chair.
  double min_overlap_other_label = 0.5;
  // A segment that is a view of several objects of its label merges them when it also covers at
  // least this share of each one's cells besides the first: one view of a whole table joins the
  // two ends that other views saw apart, while a label bleeding from one monitor over the desk
  // to the next joins nothing.
  double min_merge_cover = 0.5;
  // At the end, two objects of one label are fragments of one when this share of the smaller
  // one's cells are also the other's: views that each saw a part, joined by views between them.
  double min_fragment_overlap = 0.1;
  // ... and a small object (at most this share of the other's cells) whose cells come within
  // fragment_reach of the other's is a part no view showed joined to it: a table leg under a
  // top whose underside the camera never sees.
  double max_part_share = 0.1;
  double fragment_reach = 0.25;  // metres: a leg seen below the top's edge
};

// One static object as the keyframes saw it.
struct ObservedObject {
  std::uint16_t instance = 0;  // the segmentation's instance id of its views (0 = none given)
  std::map<std::uint8_t, int> label_votes;  // keyframes that saw it with each label
  std::vector<std::uint64_t> keyframes;     // ids of the keyframes that saw it, ascending
  std::unordered_map<std::uint64_t, int> cell_counts;   // keyframes that saw each cell
  Eigen::Vector3d point_sum = Eigen::Vector3d::Zero();  // of its segments' points
  std::size_t point_count = 0;

  // The label with the most votes (ties: the smaller id); 0 before any vote.
  [[nodiscard]] std::uint8_t label() const;
  // Share of the votes that went to label().
  [[nodiscard]] double confidence() const;
  [[nodiscard]] Eigen::Vector3f centroid() const;
};

// Associates each keyframe's labelled segments (world frame) with the objects of the keyframes
// before it, by 3D overlap and label, so that an object seen from many keyframes is one object
// with one vote per keyframe for the label it was seen with. A segment that overlaps several
// objects of its label joins them: the fragments that separate views made are merged. Where the
// segmentation tracks instances (an instance id on the segment), the id decides instead: views
// with one id are one object, objects with two ids never merge.
class ObjectAssociator {
 public:
  ObjectAssociator(double cell_size, ObjectAssociationOptions options);

  // Keyframes in time order; `segments` from segmentByLabel with this associator's cell size.
  void addKeyFrame(std::uint64_t keyframe_id, const std::vector<LabelSegment>& segments);

  // The objects so far, fragments merged (min_fragment_overlap), in order of creation.
  [[nodiscard]] std::vector<ObservedObject> objects() const;
  [[nodiscard]] double cellSize() const { return cell_size_; }

 private:
  struct KeyFrameView {  // what one keyframe saw of one object
    std::map<std::uint8_t, std::size_t> label_points;
    std::vector<std::uint64_t> cells;
    Eigen::Vector3d point_sum = Eigen::Vector3d::Zero();
    std::size_t point_count = 0;
  };

  // The object that absorbed `object` (itself when not merged).
  [[nodiscard]] std::size_t resolve(std::size_t object) const;
  // Cells of the segment that lie on or next to (26-neighbours) each (resolved) object: views of
  // one surface whose depth noise puts them in neighbouring cells still overlap.
  [[nodiscard]] std::map<std::size_t, std::size_t> overlaps(const LabelSegment& segment) const;
  [[nodiscard]] std::vector<std::size_t> matches(const LabelSegment& segment) const;
  void merge(std::size_t from, std::size_t into);
  static void merge(ObservedObject& source, ObservedObject& target);
  // Whether `a` and `b` (same label) are fragments of one object.
  [[nodiscard]] bool fragmentsOfOne(const ObservedObject& a, const ObservedObject& b) const;
  // Whether a cell of `part` lies within fragment_reach of a cell of `whole`.
  [[nodiscard]] bool withinReach(const ObservedObject& part, const ObservedObject& whole) const;
  void record(std::size_t object, std::uint64_t keyframe_id, KeyFrameView view);

  double cell_size_;
  ObjectAssociationOptions options_;
  std::vector<ObservedObject> objects_;
  std::vector<std::size_t> merged_into_;  // objects_[i] went into objects_[merged_into_[i]]
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> objects_at_cell_;
};

}  // namespace segslam::dense
