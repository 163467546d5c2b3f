#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace segslam::dense {

using Rgb = std::array<std::uint8_t, 3>;

// A coloured point cloud whose points also carry a semantic label (core::SemanticClass id,
// 0 = unknown) and an instance id (0 = none). The arrays always have the same length.
struct LabelledCloud {
  std::vector<Eigen::Vector3f> points;
  std::vector<Rgb> colours;
  std::vector<std::uint8_t> labels;
  std::vector<std::uint16_t> instances;

  [[nodiscard]] std::size_t size() const { return points.size(); }
  [[nodiscard]] bool empty() const { return points.empty(); }
  void reserve(std::size_t n);
  void add(const Eigen::Vector3f& point, const Rgb& colour, std::uint8_t label = 0,
           std::uint16_t instance = 0);
  void append(const LabelledCloud& other);
  // The points at `indices`, in that order.
  [[nodiscard]] LabelledCloud select(const std::vector<std::size_t>& indices) const;
};

// Every point mapped by `transform` (e.g. camera to world).
LabelledCloud transformed(const LabelledCloud& cloud, const Eigen::Isometry3d& transform);

// One point per occupied cube of a grid with edge `voxel_size` (> 0): the mean position and
// colour of the points in it, their most frequent label and, among the points with that label,
// their most frequent instance (ties: the smaller id); ordered by voxel. Our own grid rather than
// Open3D's VoxelDownSampleAndTrace, which carries labels too but keeps a list of members per
// voxel: with it a keyframe cloud took seconds on a busy machine.
LabelledCloud voxelDownsample(const LabelledCloud& cloud, double voxel_size);

}  // namespace segslam::dense
