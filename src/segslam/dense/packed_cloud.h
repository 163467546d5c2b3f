#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "segslam/dense/keyframe_cloud.h"
#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

// A LabelledCloud as the map keeps it between keyframes: 12 bytes a point instead of 18, the
// coordinates in whole millimetres (16 bits each). A map of 1 cm voxels loses nothing a depth
// camera measures (at most 0.5 mm per axis), and a live keyframe's cloud, most of what a long
// session holds per keyframe, takes a third less memory. Points more than 32.767 m from the
// origin along an axis are dropped: in a keyframe's camera frame no 5 m depth camera sees them.
class PackedCloud {
 public:
  PackedCloud() = default;
  explicit PackedCloud(const LabelledCloud& cloud);

  [[nodiscard]] LabelledCloud unpacked() const;
  [[nodiscard]] std::size_t size() const { return points_.size(); }
  [[nodiscard]] bool empty() const { return points_.empty(); }

 private:
  struct Point {
    std::array<std::int16_t, 3> mm;
    Rgb colour;
    std::uint8_t label;
    std::uint16_t instance;
  };
  static_assert(sizeof(Point) == 12);

  std::vector<Point> points_;
};

// The three layers of a KeyFrameCloud, packed.
struct PackedKeyFrameCloud {
  PackedKeyFrameCloud() = default;
  explicit PackedKeyFrameCloud(const KeyFrameCloud& cloud);
  [[nodiscard]] KeyFrameCloud unpacked() const;

  PackedCloud static_points;
  PackedCloud dynamic_points;
  PackedCloud folded_points;
};

}  // namespace segslam::dense
