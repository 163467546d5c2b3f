#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace segslam::dense {

// Integer coordinates of the grid cell of edge `cell_size` that holds `point`.
inline Eigen::Vector3i cellOf(const Eigen::Vector3f& point, double cell_size) {
  return {static_cast<int>(std::floor(point.x() / cell_size)),
          static_cast<int>(std::floor(point.y() / cell_size)),
          static_cast<int>(std::floor(point.z() / cell_size))};
}

// Cell coordinates packed into one integer, 21 bits per axis (+-10 km at 1 cm), so that cells can
// be sorted and hashed.
inline std::uint64_t packCell(const Eigen::Vector3i& cell) {
  std::uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    key = (key << 21) | (static_cast<std::uint64_t>(cell[axis] + (1 << 20)) & ((1u << 21) - 1));
  }
  return key;
}

inline Eigen::Vector3i unpackCell(std::uint64_t key) {
  Eigen::Vector3i cell;
  for (int axis = 2; axis >= 0; --axis) {
    cell[axis] = static_cast<int>(key & ((1u << 21) - 1)) - (1 << 20);
    key >>= 21;
  }
  return cell;
}

inline std::uint64_t voxelKey(const Eigen::Vector3f& point, double voxel_size) {
  return packCell(cellOf(point, voxel_size));
}

}  // namespace segslam::dense
