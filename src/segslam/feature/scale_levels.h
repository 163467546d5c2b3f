#pragma once

#include <vector>

namespace segslam::feature {

// The scales of an image pyramid: level l is the image shrunk by factor^l. Tracking needs the
// per-level figures too: a keypoint found at level l is localised to about factor^l pixels, so
// its reprojection error gets variance sigma^2 = factor^(2l) (as in ORB-SLAM).
class ScaleLevels {
 public:
  // Throws std::invalid_argument unless num_levels >= 1 and factor > 1.
  ScaleLevels(int num_levels, double factor);

  [[nodiscard]] int numLevels() const { return static_cast<int>(scales_.size()); }
  [[nodiscard]] double factor() const { return factor_; }
  // factor^level: multiplies level coordinates into level-0 pixels.
  [[nodiscard]] const std::vector<double>& scales() const { return scales_; }
  [[nodiscard]] const std::vector<double>& inverseScales() const { return inverse_scales_; }
  // factor^(2 level) and its inverse (information weight).
  [[nodiscard]] const std::vector<double>& sigma2() const { return sigma2_; }
  [[nodiscard]] const std::vector<double>& inverseSigma2() const { return inverse_sigma2_; }

 private:
  double factor_;
  std::vector<double> scales_;
  std::vector<double> inverse_scales_;
  std::vector<double> sigma2_;
  std::vector<double> inverse_sigma2_;
};

}  // namespace segslam::feature
