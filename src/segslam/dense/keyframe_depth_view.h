#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <limits>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/dense/label_segments.h"
#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

struct KeyFrameDepthViewOptions {
  int cell_px = 10;      // the view is kept as a grid of cells this many pixels wide
  int window_cells = 1;  // a place is looked at through this many cells around it, each side
  // A place is a segment's points' centroid, on the surface the camera saw of them (a partial
  // view's). A surface this much in front of it hides it (m)...
  double hiding_margin = 0.3;
  // ...and a static one this much behind it shows it empty: beyond the depth noise and a body's
  // curve, so that a person the mask missed is not taken for the wall behind them.
  double behind_margin = 0.1;
};

// What a keyframe showed at a place: nothing it can tell (out of view, no depth there, something
// static in front of it), a static surface well behind it (the place is empty: whoever was there
// has left), a static surface at it (a static thing there, or a person there whom the mask
// missed), or a segment of its dynamic layer at, before or behind it.
struct PlaceSight {
  enum class Kind { kUnseen, kEmpty, kStatic, kSegment };
  Kind kind = Kind::kUnseen;
  std::size_t segment = std::numeric_limits<std::size_t>::max();  // for kSegment
  bool in_front = false;  // for kSegment: the segment stands before the place, hiding it
};

// One keyframe's view as a coarse depth grid of both its layers: for each cell the nearest point
// and what it is (static, or which dynamic segment). A default-constructed view sees nothing.
class KeyFrameDepthView {
 public:
  KeyFrameDepthView() = default;
  // Points in the world frame; `segments` index `dynamic_points`.
  KeyFrameDepthView(const core::Camera& camera, const Eigen::Isometry3d& T_cw,
                    const LabelledCloud& static_points, const LabelledCloud& dynamic_points,
                    const std::vector<LabelSegment>& segments,
                    KeyFrameDepthViewOptions options = {});

  [[nodiscard]] PlaceSight look(const Eigen::Vector3f& place_w) const;

  // Whether the view shows a static surface well behind the line between two places (the
  // segments' centroids): the room seen between them, so that they are two things standing apart,
  // not one person cut in two by something in front (a table edge) or by a mask's gap.
  [[nodiscard]] bool showsBackgroundBetween(const Eigen::Vector3f& a_w,
                                            const Eigen::Vector3f& b_w) const;

 private:
  static constexpr int kStatic = -1;
  static constexpr int kUnsegmented = -2;
  struct Cell {
    float depth = std::numeric_limits<float>::max();
    int owner = kUnsegmented;  // kStatic, kUnsegmented or a segment index
  };

  void draw(const LabelledCloud& cloud, const std::vector<int>& owners);
  [[nodiscard]] bool project(const Eigen::Vector3f& point_w, int& col, int& row,
                             float& depth) const;

  core::Camera camera_;
  Eigen::Isometry3f T_cw_ = Eigen::Isometry3f::Identity();
  KeyFrameDepthViewOptions options_;
  int cols_ = 0;
  int rows_ = 0;
  std::vector<Cell> cells_;
};

}  // namespace segslam::dense
