#include "segslam/place/masked_similarity.h"

#include <vector>

namespace segslam::place {

namespace {

// An average over a few pixels of a cell is noise.
constexpr double kMinPooledArea = 0.1;

// Columns that average each cell's static area: features x pooling = cell means.
cv::Mat poolingMatrix(const cv::Mat& weights, cv::Size grid, cv::Size cells) {
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
      if (area < kMinPooledArea * (x1 - x0) * (y1 - y0)) continue;
      columns.push_back(column / area);
    }
  }
  cv::Mat pooling;
  if (!columns.empty()) cv::hconcat(columns, pooling);
  return pooling;
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
  const cv::Size clamped(std::min(cells.width, grid.width), std::min(cells.height, grid.height));
  const cv::Mat pooling = poolingMatrix(weights, grid, clamped);
  if (pooling.empty()) return 0.0;
  return cosineSimilarity(a * pooling, b * pooling);
}

}  // namespace segslam::place
