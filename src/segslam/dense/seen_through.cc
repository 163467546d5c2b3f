#include "segslam/dense/seen_through.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace segslam::dense {

namespace {

// Depth sensors place one surface a few centimetres apart from view to view, more far away.
constexpr float kMarginM = 0.05f;
constexpr float kMarginPerMetre = 0.02f;

}  // namespace

FreeSpaceView::FreeSpaceView(const core::Camera& camera, const KeyFrameCloud& cloud, int cell_px,
                             int min_points)
    : camera_(camera),
      cell_px_(std::max(cell_px, 1)),
      min_points_(min_points),
      cols_((camera.width + cell_px_ - 1) / cell_px_),
      rows_((camera.height + cell_px_ - 1) / cell_px_),
      nearest_(static_cast<std::size_t>(cols_) * rows_, std::numeric_limits<float>::max()),
      points_(nearest_.size(), 0) {
  for (const LabelledCloud* layer : {&cloud.static_points, &cloud.dynamic_points}) {
    for (const Eigen::Vector3f& p : layer->points) {
      if (p.z() <= 0.0f) continue;
      const Eigen::Vector2d pixel = camera_.project(p.cast<double>());
      const int col = static_cast<int>(std::floor(pixel.x() / cell_px_));
      const int row = static_cast<int>(std::floor(pixel.y() / cell_px_));
      if (col < 0 || row < 0 || col >= cols_ || row >= rows_) continue;
      const std::size_t cell = static_cast<std::size_t>(row) * cols_ + col;
      nearest_[cell] = std::min(nearest_[cell], p.z());
      ++points_[cell];
    }
  }
}

bool FreeSpaceView::seesThrough(const Eigen::Vector3f& point_c) const {
  if (point_c.z() <= 0.0f) return false;
  const Eigen::Vector2d pixel = camera_.project(point_c.cast<double>());
  const int col = static_cast<int>(std::floor(pixel.x() / cell_px_));
  const int row = static_cast<int>(std::floor(pixel.y() / cell_px_));
  if (col < 0 || row < 0 || col >= cols_ || row >= rows_) return false;
  const std::size_t cell = static_cast<std::size_t>(row) * cols_ + col;
  if (points_[cell] < min_points_) return false;
  return nearest_[cell] > point_c.z() * (1.0f + kMarginPerMetre) + kMarginM;
}

LabelledCloud withoutSeenThrough(
    const LabelledCloud& earlier, const core::Camera& camera,
    const std::vector<std::pair<Eigen::Isometry3d, const KeyFrameCloud*>>& views) {
  std::vector<FreeSpaceView> free_space;
  std::vector<Eigen::Isometry3f> T_cw;
  for (const auto& [T_wc, cloud] : views) {
    free_space.emplace_back(camera, *cloud);
    T_cw.push_back(T_wc.inverse().cast<float>());
  }
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < earlier.size(); ++i) {
    bool seen_through = false;
    for (std::size_t k = 0; k < free_space.size() && !seen_through; ++k) {
      seen_through = free_space[k].seesThrough(T_cw[k] * earlier.points[i]);
    }
    if (!seen_through) kept.push_back(i);
  }
  return earlier.select(kept);
}

}  // namespace segslam::dense
