#pragma once

// Synthetic images for the feature tests only (header-only, never linked into the library).

#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace segslam::feature::testing {

// A cluttered grey-level scene of random rectangles, circles and lines on a mid-grey background,
// drawn with a seeded RNG (same seed, same image): plenty of FAST corners everywhere, no two
// regions alike. A light blur gives the edges the anti-aliasing a camera would.
inline cv::Mat texturedImage(cv::Size size, std::uint64_t seed, int shapes = 900,
                             int contrast = 255) {
  cv::Mat image(size, CV_8UC1, cv::Scalar(128));
  cv::RNG rng(seed);
  const auto gray = [&] { return cv::Scalar(128 + rng.uniform(-contrast / 2, contrast / 2 + 1)); };
  const auto point = [&] {
    return cv::Point(rng.uniform(0, size.width), rng.uniform(0, size.height));
  };
  for (int i = 0; i < shapes; ++i) {
    const cv::Point p = point();
    switch (i % 3) {
      case 0:
        cv::rectangle(image, p, p + cv::Point(rng.uniform(4, 40), rng.uniform(4, 40)), gray(),
                      cv::FILLED);
        break;
      case 1:
        cv::circle(image, p, rng.uniform(3, 20), gray(), cv::FILLED);
        break;
      default:
        cv::line(image, p, p + cv::Point(rng.uniform(-30, 30), rng.uniform(-30, 30)), gray(), 2);
    }
  }
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  return image;
}

}  // namespace segslam::feature::testing
