#pragma once

// Labelled boxes for the object-map tests (header-only, never linked into the library).

#include <Eigen/Core>
#include <cstdint>

#include "segslam/core/semantic_class.h"
#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense::test_clouds {

// The surface of the axis-aligned box [min, max] sampled on a 1 cm grid.
inline void addBox(LabelledCloud& cloud, const Eigen::Vector3f& min, const Eigen::Vector3f& max,
                   core::SemanticClass label, std::uint16_t instance = 0) {
  const Eigen::Vector3i cells = ((max - min) / 0.01f).array().round().cast<int>();
  for (int i = 0; i <= cells.x(); ++i) {
    for (int j = 0; j <= cells.y(); ++j) {
      for (int k = 0; k <= cells.z(); ++k) {
        const bool on_surface =
            i == 0 || j == 0 || k == 0 || i == cells.x() || j == cells.y() || k == cells.z();
        if (!on_surface) continue;
        const Eigen::Vector3f offset = 0.01f * Eigen::Vector3f(i, j, k);
        cloud.add(min + offset, {1, 2, 3}, static_cast<std::uint8_t>(label), instance);
      }
    }
  }
}

inline LabelledCloud box(const Eigen::Vector3f& min, const Eigen::Vector3f& max,
                         core::SemanticClass label, std::uint16_t instance = 0) {
  LabelledCloud cloud;
  addBox(cloud, min, max, label, instance);
  return cloud;
}

}  // namespace segslam::dense::test_clouds
