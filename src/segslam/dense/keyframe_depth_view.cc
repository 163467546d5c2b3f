#include "segslam/dense/keyframe_depth_view.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace segslam::dense {

KeyFrameDepthView::KeyFrameDepthView(const core::Camera& camera, const Eigen::Isometry3d& T_cw,
                                     const LabelledCloud& static_points,
                                     const LabelledCloud& dynamic_points,
                                     const std::vector<LabelSegment>& segments,
                                     KeyFrameDepthViewOptions options)
    : camera_(camera),
      T_cw_(T_cw.cast<float>()),
      options_(options),
      cols_((camera.width + options.cell_px - 1) / options.cell_px),
      rows_((camera.height + options.cell_px - 1) / options.cell_px),
      cells_(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_)) {
  draw(static_points, std::vector<int>(static_points.size(), kStatic));
  std::vector<int> owners(dynamic_points.size(), kUnsegmented);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (std::size_t i : segments[s].indices) owners[i] = static_cast<int>(s);
  }
  draw(dynamic_points, owners);
}

bool KeyFrameDepthView::project(const Eigen::Vector3f& point_w, int& col, int& row,
                                float& depth) const {
  if (cells_.empty()) return false;
  const Eigen::Vector3f p = T_cw_ * point_w;
  if (!(p.z() > 0.0f)) return false;
  const double u = camera_.fx * p.x() / p.z() + camera_.cx;
  const double v = camera_.fy * p.y() / p.z() + camera_.cy;
  if (!(u >= 0.0 && v >= 0.0 && u < camera_.width && v < camera_.height)) return false;
  col = static_cast<int>(u) / options_.cell_px;
  row = static_cast<int>(v) / options_.cell_px;
  depth = p.z();
  return true;
}

void KeyFrameDepthView::draw(const LabelledCloud& cloud, const std::vector<int>& owners) {
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    int col = 0;
    int row = 0;
    float depth = 0.0f;
    if (!project(cloud.points[i], col, row, depth)) continue;
    Cell& cell = cells_[static_cast<std::size_t>(row * cols_ + col)];
    if (depth < cell.depth) cell = {depth, owners[i]};
  }
}

PlaceSight KeyFrameDepthView::look(const Eigen::Vector3f& place_w) const {
  int col = 0;
  int row = 0;
  float depth = 0.0f;
  if (!project(place_w, col, row, depth)) return {};
  // The nearest surface around the place decides: a person still there is nearer than the wall
  // behind them, and anything static in front hides them.
  const Cell* nearest = nullptr;
  const int w = options_.window_cells;
  for (int r = std::max(0, row - w); r <= std::min(rows_ - 1, row + w); ++r) {
    for (int c = std::max(0, col - w); c <= std::min(cols_ - 1, col + w); ++c) {
      const Cell& cell = cells_[static_cast<std::size_t>(r * cols_ + c)];
      if (!nearest || cell.depth < nearest->depth) nearest = &cell;
    }
  }
  if (nearest->depth == std::numeric_limits<float>::max() || nearest->owner == kUnsegmented) {
    return {};
  }
  const bool in_front = nearest->depth < depth - static_cast<float>(options_.hiding_margin);
  // Static points at the place may be the person themselves, missed by the mask: only a surface
  // behind it shows it empty.
  if (nearest->owner == kStatic) {
    const auto behind_margin = static_cast<float>(options_.behind_margin);
    if (nearest->depth > depth + behind_margin) return {PlaceSight::Kind::kEmpty};
    return nearest->depth >= depth - behind_margin ? PlaceSight{PlaceSight::Kind::kStatic}
                                                   : PlaceSight{};
  }
  return {PlaceSight::Kind::kSegment, static_cast<std::size_t>(nearest->owner), in_front};
}

bool KeyFrameDepthView::showsBackgroundBetween(const Eigen::Vector3f& a_w,
                                               const Eigen::Vector3f& b_w) const {
  int a_col = 0;
  int a_row = 0;
  float a_depth = 0.0f;
  int b_col = 0;
  int b_row = 0;
  float b_depth = 0.0f;
  if (!project(a_w, a_col, a_row, a_depth) || !project(b_w, b_col, b_row, b_depth)) return false;
  const int steps = std::max(std::abs(b_col - a_col), std::abs(b_row - a_row));
  for (int step = 1; step < steps; ++step) {
    const float t = static_cast<float>(step) / static_cast<float>(steps);
    const int col = static_cast<int>(
        std::lround(static_cast<float>(a_col) + t * static_cast<float>(b_col - a_col)));
    const int row = static_cast<int>(
        std::lround(static_cast<float>(a_row) + t * static_cast<float>(b_row - a_row)));
    const Cell& cell = cells_[static_cast<std::size_t>(row * cols_ + col)];
    const float depth = a_depth + t * (b_depth - a_depth);
    // Whatever is seen there, static or under a mask but of no segment (a mask spilling over
    // the room between two people), well behind the line is the room.
    if ((cell.owner == kStatic || cell.owner == kUnsegmented) &&
        cell.depth > depth + static_cast<float>(options_.behind_margin)) {
      return true;
    }
  }
  return false;
}

}  // namespace segslam::dense
