#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

namespace segslam::synth {

// A colour image laid on a surface: texel (i, j) covers [i, i+1) x [j, j+1) texel sizes of the
// surface coordinates (s, t) in metres. Sampling is mip-mapped (bilinear within a level, blended
// between levels near their switch) so that distant or slanted surfaces do not alias; beyond the
// image the border texels repeat.
class Texture {
 public:
  // `image`: CV_8UC3 (BGR), at least 1x1; `texel_size`: metres per texel.
  Texture(const cv::Mat& image, double texel_size);

  // BGR colour (0..255) at surface coordinates (s, t) metres, filtered for a pixel that covers
  // `footprint` metres of the surface.
  [[nodiscard]] Eigen::Vector3f sample(double s, double t, double footprint) const;

  [[nodiscard]] double texelSize() const { return texel_size_; }
  [[nodiscard]] int levelCount() const { return static_cast<int>(levels_.size()); }
  [[nodiscard]] const cv::Mat& level(int i) const { return levels_[i]; }

 private:
  [[nodiscard]] Eigen::Vector3f bilinear(int level, double x, double y) const;

  std::vector<cv::Mat> levels_;  // levels_[0] is the full image, each next one half the size
  std::vector<double> texels_per_metre_;  // per level
  double texel_size_;
};

}  // namespace segslam::synth
