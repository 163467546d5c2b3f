#include "segslam/segmentation/strongest_corners.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "segslam/util/error.h"

namespace segslam::segmentation {

namespace {

constexpr int kBandRows = 32;
constexpr int kBlockSize = 3;
constexpr int kSobelSize = 3;

// The smaller eigenvalue of each pixel's structure tensor, a band of rows at a time. A band is
// computed with one row more on each inner side: its gradients see the image beyond the band
// (OpenCV filters a row range with the rows around it), but the 3x3 sum of its tensor repeats
// its own edge rows, so only the band's inner rows are kept. The sums run in double over float
// products of 8-bit gradients and are exact, so every value equals the whole image's.
cv::Mat1f minEigenValues(const cv::Mat& gray) {
  cv::Mat1f eigen(gray.size());
  cv::Mat band_eigen;
  for (int first = 0; first < gray.rows; first += kBandRows) {
    const int end = std::min(gray.rows, first + kBandRows);
    const int top = std::max(0, first - 1);
    const int bottom = std::min(gray.rows, end + 1);
    cv::cornerMinEigenVal(gray.rowRange(top, bottom), band_eigen, kBlockSize, kSobelSize);
    band_eigen.rowRange(first - top, end - top).copyTo(eigen.rowRange(first, end));
  }
  return eigen;
}

struct Candidate {
  float strength;
  int index;  // y * cols + x
};

// Pixels off the image's outermost rows and columns whose eigenvalue exceeds `threshold` and is
// the largest of its 3x3 neighbourhood.
std::vector<Candidate> localMaxima(const cv::Mat1f& eigen, float threshold) {
  std::vector<Candidate> candidates;
  for (int y = 1; y + 1 < eigen.rows; ++y) {
    const float* above = eigen[y - 1];
    const float* row = eigen[y];
    const float* below = eigen[y + 1];
    for (int x = 1; x + 1 < eigen.cols; ++x) {
      const float value = row[x];
      if (!(value > threshold)) continue;
      const float neighbours = std::max({above[x - 1], above[x], above[x + 1], row[x - 1],
                                         row[x + 1], below[x - 1], below[x], below[x + 1]});
      if (value >= neighbours) candidates.push_back({value, y * eigen.cols + x});
    }
  }
  return candidates;
}

// Strongest first; equal strengths the later pixel first, as OpenCV orders them.
bool stronger(const Candidate& a, const Candidate& b) {
  if (a.strength != b.strength) return a.strength > b.strength;
  return a.index > b.index;
}

// Keeps candidates in order unless a kept one lies closer than min_distance, up to max_corners
// (all when max_corners <= 0). Kept corners are filed in cells of min_distance, so each
// candidate looks only at the 3x3 cells around it.
std::vector<cv::Point2f> spreadOut(const std::vector<Candidate>& candidates, int cols, int rows,
                                   int max_corners, double min_distance) {
  std::vector<cv::Point2f> kept;
  const int cell = std::max(1, static_cast<int>(std::lround(min_distance)));
  const int grid_cols = (cols + cell - 1) / cell;
  const int grid_rows = (rows + cell - 1) / cell;
  std::vector<std::vector<cv::Point2f>> grid(static_cast<std::size_t>(grid_cols * grid_rows));
  const auto min_squared = static_cast<float>(min_distance * min_distance);
  for (const Candidate& candidate : candidates) {
    const cv::Point2f point(static_cast<float>(candidate.index % cols),
                            static_cast<float>(candidate.index / cols));
    const int cell_x = candidate.index % cols / cell;
    const int cell_y = candidate.index / cols / cell;
    bool clear = true;
    for (int gy = std::max(0, cell_y - 1); clear && gy <= std::min(grid_rows - 1, cell_y + 1);
         ++gy) {
      for (int gx = std::max(0, cell_x - 1); clear && gx <= std::min(grid_cols - 1, cell_x + 1);
           ++gx) {
        for (const cv::Point2f& other : grid[static_cast<std::size_t>(gy * grid_cols + gx)]) {
          const cv::Point2f d = point - other;
          if (d.x * d.x + d.y * d.y < min_squared) {
            clear = false;
            break;
          }
        }
      }
    }
    if (!clear) continue;
    grid[static_cast<std::size_t>(cell_y * grid_cols + cell_x)].push_back(point);
    kept.push_back(point);
    if (max_corners > 0 && static_cast<int>(kept.size()) == max_corners) break;
  }
  return kept;
}

}  // namespace

std::vector<cv::Point2f> strongestCorners(const cv::Mat& gray, int max_corners,
                                          double quality_level, double min_distance) {
  if (gray.empty()) return {};
  if (gray.type() != CV_8UC1) throw util::Error("strongestCorners: needs an 8-bit grey image");
  const cv::Mat1f eigen = minEigenValues(gray);
  double strongest = 0.0;
  cv::minMaxLoc(eigen, nullptr, &strongest);
  std::vector<Candidate> candidates =
      localMaxima(eigen, static_cast<float>(strongest * quality_level));
  std::sort(candidates.begin(), candidates.end(), stronger);
  return spreadOut(candidates, gray.cols, gray.rows, max_corners, min_distance);
}

}  // namespace segslam::segmentation
