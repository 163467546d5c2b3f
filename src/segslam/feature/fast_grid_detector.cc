#include "segslam/feature/fast_grid_detector.h"

#include <algorithm>
#include <cmath>
#include <opencv2/features2d.hpp>

namespace segslam::feature {
namespace {

// FAST tests a circle of radius 3, so it only reports pixels 3 inside the image it is given.
constexpr int kFastRadius = 3;

// In float, exactly as the extractor scales the keypoints it reports, so that the mask is asked
// about the very pixel a reported keypoint rounds to.
cv::Point toLevel0(const cv::Point2f& level_point, const LevelToBase& to_base) {
  const cv::Point2f base = to_base(level_point);
  return {cvRound(base.x), cvRound(base.y)};
}

// The level-0 pixels that the pixels of a level rectangle map to, first to last.
cv::Rect toLevel0(const cv::Rect& level_rect, const LevelToBase& to_base) {
  const cv::Point first = toLevel0(cv::Point2f(level_rect.tl()), to_base);
  const cv::Point last = toLevel0(cv::Point2f(level_rect.br() - cv::Point(1, 1)), to_base);
  return {first, last + cv::Point(1, 1)};
}

// The cells of the detection region: columns x rows of nearly equal, roughly cell_size squares.
class CellGrid {
 public:
  CellGrid(const cv::Rect& region, int cell_size)
      : region_(region),
        columns_(partCount(region.width, cell_size)),
        rows_(partCount(region.height, cell_size)) {}

  [[nodiscard]] int size() const { return columns_ * rows_; }
  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }

  // Cells [first_column, end_column) of a row, as one rectangle.
  [[nodiscard]] cv::Rect span(int row, int first_column, int end_column) const {
    const int x0 = partStart(region_.x, region_.width, columns_, first_column);
    const int x1 = partStart(region_.x, region_.width, columns_, end_column);
    const int y0 = partStart(region_.y, region_.height, rows_, row);
    const int y1 = partStart(region_.y, region_.height, rows_, row + 1);
    return {x0, y0, x1 - x0, y1 - y0};
  }

  // The cell holding a pixel of the region (the inverse of partStart's rounding down).
  [[nodiscard]] int cellOf(const cv::Point2f& point) const {
    const int column = partOf(cvRound(point.x) - region_.x, region_.width, columns_);
    const int row = partOf(cvRound(point.y) - region_.y, region_.height, rows_);
    return row * columns_ + column;
  }

 private:
  static int partCount(int extent, int cell_size) {
    return std::max(1, static_cast<int>(std::lround(static_cast<double>(extent) / cell_size)));
  }
  // Start of part `index` of `count` nearly equal parts of [begin, begin + extent).
  static int partStart(int begin, int extent, int count, int index) {
    return begin + static_cast<int>(static_cast<long>(extent) * index / count);
  }
  // Part holding offset o: the largest index with floor(extent * index / count) <= o, which is
  // ceil((o + 1) * count / extent) - 1 = floor(((o + 1) * count - 1) / extent).
  static int partOf(int offset, int extent, int count) {
    const long index = ((static_cast<long>(offset) + 1) * count - 1) / extent;
    return std::clamp(static_cast<int>(index), 0, count - 1);
  }

  cv::Rect region_;
  int columns_;
  int rows_;
};

class GridDetector {
 public:
  GridDetector(const cv::Mat& image, const LevelToBase& to_base, const StaticMask& mask,
               const FastGridOptions& options)
      : image_(image), to_base_(to_base), mask_(mask), options_(options) {}

  std::vector<cv::KeyPoint> detect(const cv::Rect& region) {
    const CellGrid grid(region, options_.cell_size);
    // One FAST call over the whole region at the initial threshold finds exactly the corners
    // per-cell calls would (bar non-maximum suppression across cell borders): a call costs
    // microseconds of overhead, and a frame has a thousand cells. Corners are then sorted into
    // their cells. Likewise each run of neighbouring cells that needs the lower threshold gets
    // one call.
    fast(region, options_.initial_threshold, found_);
    sortIntoCells(grid);
    std::vector<cv::KeyPoint> corners;
    for (int row = 0; row < grid.rows(); ++row) {
      int run_start = -1;  // first column of the current run of cells needing the fallback
      for (int column = 0; column <= grid.columns(); ++column) {
        const bool needs_fallback =
            column < grid.columns() && !addStrongCorners(grid, row, column, corners);
        if (needs_fallback && run_start < 0) run_start = column;
        if (!needs_fallback && run_start >= 0) {
          addFallbackCorners(grid.span(row, run_start, column), corners);
          run_start = -1;
        }
      }
    }
    return corners;
  }

  // FAST corners whose centres lie in `area`, in image coordinates.
  void fast(const cv::Rect& area, int threshold, std::vector<cv::KeyPoint>& corners) const {
    const cv::Rect window(area.x - kFastRadius, area.y - kFastRadius, area.width + 2 * kFastRadius,
                          area.height + 2 * kFastRadius);
    cv::FAST(image_(window), corners, threshold, /*nonmaxSuppression=*/true);
    for (cv::KeyPoint& corner : corners) {
      corner.pt.x += static_cast<float>(window.x);
      corner.pt.y += static_cast<float>(window.y);
    }
  }

  // Counting sort of found_ by cell, keeping FAST's order within a cell.
  void sortIntoCells(const CellGrid& grid) {
    cell_begin_.assign(grid.size() + 1, 0);
    cell_of_.clear();
    for (const cv::KeyPoint& corner : found_) {
      cell_of_.push_back(grid.cellOf(corner.pt));
      ++cell_begin_[cell_of_.back() + 1];
    }
    for (int index = 0; index < grid.size(); ++index) cell_begin_[index + 1] += cell_begin_[index];
    by_cell_.resize(found_.size());
    std::vector<int> next(cell_begin_.begin(), cell_begin_.end() - 1);
    for (std::size_t i = 0; i < found_.size(); ++i) by_cell_[next[cell_of_[i]]++] = found_[i];
  }

  // Appends the static corners the initial threshold found in a cell. Returns false when the cell
  // has none but could have some at the lower threshold.
  bool addStrongCorners(const CellGrid& grid, int row, int column,
                        std::vector<cv::KeyPoint>& corners) const {
    const cv::Rect cell0 = toLevel0(grid.span(row, column, column + 1), to_base_);
    if (mask_.isDynamicRect(cell0)) return true;
    const int index = row * grid.columns() + column;
    const std::size_t before = corners.size();
    appendStatic(by_cell_.begin() + cell_begin_[index], by_cell_.begin() + cell_begin_[index + 1],
                 !mask_.isStaticRect(cell0), corners);
    return corners.size() > before || options_.min_threshold >= options_.initial_threshold;
  }

  void addFallbackCorners(const cv::Rect& cells, std::vector<cv::KeyPoint>& corners) {
    fast(cells, options_.min_threshold, fallback_);
    appendStatic(fallback_.begin(), fallback_.end(), !mask_.isStaticRect(toLevel0(cells, to_base_)),
                 corners);
  }

  void appendStatic(std::vector<cv::KeyPoint>::const_iterator begin,
                    std::vector<cv::KeyPoint>::const_iterator end, bool needs_check,
                    std::vector<cv::KeyPoint>& corners) const {
    for (auto corner = begin; corner != end; ++corner) {
      if (!needs_check || mask_.isStatic(toLevel0(corner->pt, to_base_)))
        corners.push_back(*corner);
    }
  }

  const cv::Mat& image_;
  LevelToBase to_base_;
  const StaticMask& mask_;
  const FastGridOptions& options_;
  std::vector<cv::KeyPoint> found_;
  std::vector<cv::KeyPoint> fallback_;
  std::vector<cv::KeyPoint> by_cell_;
  std::vector<int> cell_of_;
  std::vector<int> cell_begin_;
};

}  // namespace

cv::Rect detectionRegion(cv::Size level_size, int border) {
  const int width = level_size.width - 2 * border;
  const int height = level_size.height - 2 * border;
  if (width <= 0 || height <= 0) return {};
  return {border, border, width, height};
}

std::vector<cv::KeyPoint> detectFastInGrid(const cv::Mat& level_image, const LevelToBase& to_base,
                                           const StaticMask& static_mask,
                                           const FastGridOptions& options) {
  const cv::Rect region =
      detectionRegion(level_image.size(), std::max(options.border, kFastRadius));
  if (region.empty()) return {};
  return GridDetector(level_image, to_base, static_mask, options).detect(region);
}

}  // namespace segslam::feature
