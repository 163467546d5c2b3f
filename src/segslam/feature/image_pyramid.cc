#include "segslam/feature/image_pyramid.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace segslam::feature {

cv::Size pyramidLevelSize(cv::Size size, double scale) {
  // At least one pixel, so that cv::resize accepts tiny images; they just yield no keypoints.
  const auto shrink = [scale](int extent) {
    return std::max(1, static_cast<int>(std::lround(extent / scale)));
  };
  return {shrink(size.width), shrink(size.height)};
}

LevelToBase LevelToBase::between(cv::Size base, cv::Size level) {
  return {static_cast<float>(base.width) / static_cast<float>(level.width),
          static_cast<float>(base.height) / static_cast<float>(level.height)};
}

void buildImagePyramid(const cv::Mat& gray, const ScaleLevels& scale_levels,
                       std::vector<cv::Mat>& levels) {
  const int num_levels = scale_levels.numLevels();
  levels.resize(num_levels);
  levels[0] = gray;
  for (int level = 1; level < num_levels; ++level) {
    const cv::Size size = pyramidLevelSize(gray.size(), scale_levels.scales()[level]);
    cv::resize(levels[level - 1], levels[level], size, 0.0, 0.0, cv::INTER_LINEAR);
  }
}

}  // namespace segslam::feature
