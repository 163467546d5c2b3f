#include "segslam/place/masked_similarity.h"

#include <algorithm>
#include <vector>

namespace segslam::place {

namespace {

// An average over a few pixels of a cell is noise.
constexpr double kMinPooledArea = 0.1;

// One column per cell that averages the cell's static area (features x pooling = cell means);
// a cell with too little static area gets a zero column and is not `kept`.
struct CellPooling {
  cv::Mat columns;
  std::vector<bool> kept;
};

CellPooling cellPooling(const cv::Mat& weights, cv::Size grid, cv::Size cells) {
  CellPooling pooling;
  std::vector<cv::Mat> columns;
  for (int cy = 0; cy < cells.height; ++cy) {
    for (int cx = 0; cx < cells.width; ++cx) {
      const int x0 = cx * grid.width / cells.width;
      const int x1 = (cx + 1) * grid.width / cells.width;
      const int y0 = cy * grid.height / cells.height;
      const int y1 = (cy + 1) * grid.height / cells.height;
      cv::Mat column(grid.area(), 1, CV_32F, cv::Scalar(0.0));
      double area = 0.0;
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
          const int g = y * grid.width + x;
          column.at<float>(g) = weights.at<float>(g);
          area += weights.at<float>(g);
        }
      }
      const bool kept = area >= kMinPooledArea * (x1 - x0) * (y1 - y0);
      pooling.kept.push_back(kept);
      columns.push_back(kept ? cv::Mat(column / area) : cv::Mat(column * 0.0));
    }
  }
  cv::hconcat(columns, pooling.columns);
  return pooling;
}

cv::Size clampedCells(cv::Size cells, cv::Size grid) {
  return {std::min(cells.width, grid.width), std::min(cells.height, grid.height)};
}

}  // namespace

double cosineSimilarity(const cv::Mat& a, const cv::Mat& b) {
  const double norms = cv::norm(a) * cv::norm(b);
  return norms > 0.0 ? a.dot(b) / norms : 0.0;
}

double maskedCosine(const cv::Mat& a, const cv::Mat& b, const cv::Mat& weights) {
  const cv::Mat broadcast = cv::repeat(weights, a.rows, 1);
  return cosineSimilarity(a.mul(broadcast), b.mul(broadcast));
}

double pooledMaskedCosine(const cv::Mat& a, const cv::Mat& b, const cv::Mat& weights, cv::Size grid,
                          cv::Size cells) {
  // Cells left out have zero columns: they add nothing to the dot product or the norms.
  const CellPooling pooling = cellPooling(weights, grid, clampedCells(cells, grid));
  return cosineSimilarity(a * pooling.columns, b * pooling.columns);
}

double pooledOwnMaskCosine(const cv::Mat& a, const cv::Mat& b, const cv::Mat& weights_a,
                           const cv::Mat& weights_b, cv::Size grid, cv::Size cells) {
  CellPooling pooling_a = cellPooling(weights_a, grid, clampedCells(cells, grid));
  CellPooling pooling_b = cellPooling(weights_b, grid, clampedCells(cells, grid));
  for (std::size_t c = 0; c < pooling_a.kept.size(); ++c) {
    if (pooling_a.kept[c] && pooling_b.kept[c]) continue;
    pooling_a.columns.col(static_cast<int>(c)).setTo(0.0);
    pooling_b.columns.col(static_cast<int>(c)).setTo(0.0);
  }
  return cosineSimilarity(a * pooling_a.columns, b * pooling_b.columns);
}

}  // namespace segslam::place
