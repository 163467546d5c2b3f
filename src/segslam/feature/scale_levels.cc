#include "segslam/feature/scale_levels.h"

#include <stdexcept>
#include <string>

namespace segslam::feature {

ScaleLevels::ScaleLevels(int num_levels, double factor) : factor_(factor) {
  if (num_levels < 1) {
    throw std::invalid_argument("ScaleLevels: num_levels must be at least 1, got " +
                                std::to_string(num_levels));
  }
  if (!(factor > 1.0)) {
    throw std::invalid_argument("ScaleLevels: scale factor must be > 1, got " +
                                std::to_string(factor));
  }
  double scale = 1.0;
  for (int level = 0; level < num_levels; ++level) {
    scales_.push_back(scale);
    inverse_scales_.push_back(1.0 / scale);
    sigma2_.push_back(scale * scale);
    inverse_sigma2_.push_back(1.0 / (scale * scale));
    scale *= factor;
  }
}

}  // namespace segslam::feature
