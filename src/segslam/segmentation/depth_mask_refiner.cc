#include "segslam/segmentation/depth_mask_refiner.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "segslam/feature/mask_dilation.h"
#include "segslam/util/median.h"

namespace segslam::segmentation {

namespace {

// Pixels within `radius` of the mask (Euclidean); the radius reaches 48 px for an old mask.
cv::Mat grownMask(const cv::Mat& mask, int radius) {
  return feature::dilateByRows(mask, feature::discHalfWidths(radius));
}

// Pixels more than `radius` inside the mask: an erosion by the disc of offsets within `radius`
// (Euclidean), the same pixels as a distance transform's `> radius` at a seventh of its cost for
// the small radius of the interior (0.14 against 0.97 ms on a 400 x 480 window; the transform
// was a tenth of the tracking thread's time on the walker at camera rate).
cv::Mat shrunkMask(const cv::Mat& mask, int radius) {
  cv::Mat disc = cv::Mat::zeros(2 * radius + 1, 2 * radius + 1, CV_8UC1);
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      if (dx * dx + dy * dy <= radius * radius) disc.at<std::uint8_t>(dy + radius, dx + radius) = 1;
    }
  }
  cv::Mat interior;
  cv::erode(mask != 0, interior, disc);
  return interior;
}

// floodFill's mask: 1 outside the search band (and on the one-pixel frame it requires), so fills
// stop there; 0 where the object may extend.
cv::Mat fillBlocker(const cv::Mat& mask, int band_px) {
  cv::Mat blocker(mask.rows + 2, mask.cols + 2, CV_8UC1, cv::Scalar(1));
  blocker(cv::Rect(1, 1, mask.cols, mask.rows)).setTo(0, grownMask(mask, band_px));
  return blocker;
}

// The depth-connected regions reached from the mask's interior, each filled with its own value
// (2, 3, ...; 1 marks outside the band) in the blocker.
int fillRegions(const cv::Mat& interior, const cv::Mat& depth, cv::Mat& blocker,
                const DepthRefinementOptions& options) {
  cv::Mat depth_image = depth.clone();  // floodFill's signature wants a writable image
  const cv::Scalar step(options.max_depth_step_m);
  int next_value = 2;
  for (int y = 0; y < interior.rows; y += options.seed_step_px) {
    for (int x = 0; x < interior.cols; x += options.seed_step_px) {
      if (interior.at<std::uint8_t>(y, x) == 0 || depth.at<float>(y, x) <= 0.0f) continue;
      if (blocker.at<std::uint8_t>(y + 1, x + 1) != 0) continue;  // already filled
      cv::floodFill(depth_image, blocker, cv::Point(x, y), cv::Scalar(), nullptr, step, step,
                    4 | cv::FLOODFILL_MASK_ONLY | (next_value << 8));
      next_value = std::min(next_value + 1, 255);
    }
  }
  return next_value;
}

bool nearAnyDepth(float depth, const std::vector<float>& object_depths,
                  const DepthRefinementOptions& options) {
  return std::any_of(object_depths.begin(), object_depths.end(), [&](float object) {
    return std::abs(depth - object) <=
           std::max(options.object_depth_tolerance * object, options.min_object_depth_tolerance_m);
  });
}

// A region at another depth than every known object is background (uncovered inside an old
// mask). A region mostly outside the mask is the background the mask overlapped (a lagging mask's
// trailing edge, a coarse network border), or, at a known object's depth, possibly the object
// joined by depth to a surface beside it (a person at a desk at his own depth): then its part
// inside the mask is kept (keep_masked_part_of_joined_objects), for dropping it would drop the
// object.
cv::Mat objectRegions(const cv::Mat& mask, const cv::Mat& regions, const cv::Mat& depth,
                      int num_values, const std::vector<float>& object_depths,
                      const DepthRefinementOptions& options) {
  std::vector<int> inside(num_values, 0);
  std::vector<std::vector<float>> depths(num_values);
  for (int y = 0; y < mask.rows; ++y) {
    const auto* region = regions.ptr<std::uint8_t>(y);
    const auto* masked = mask.ptr<std::uint8_t>(y);
    const auto* z = depth.ptr<float>(y);
    for (int x = 0; x < mask.cols; ++x) {
      if (region[x] < 2) continue;
      depths[region[x]].push_back(z[x]);
      inside[region[x]] += masked[x] != 0;
    }
  }
  cv::Mat kept_values = cv::Mat::zeros(1, 256, CV_8UC1);
  cv::Mat clipped_values = cv::Mat::zeros(1, 256, CV_8UC1);
  for (int value = 2; value < num_values; ++value) {
    const auto area = static_cast<int>(depths[value].size());
    if (area == 0) continue;
    if (!object_depths.empty() &&
        !nearAnyDepth(util::medianInPlace(depths[value]), object_depths, options)) {
      continue;
    }
    const bool mostly_inside = 2 * inside[value] >= area;
    if (!mostly_inside && (object_depths.empty() || !options.keep_masked_part_of_joined_objects)) {
      continue;
    }
    (mostly_inside ? kept_values : clipped_values).at<std::uint8_t>(value) = 255;
  }
  cv::Mat object;
  cv::LUT(regions, kept_values, object);
  cv::Mat clipped;
  cv::LUT(regions, clipped_values, clipped);
  return object | (clipped & mask);
}

// refineMaskByDepth on the part of the image that can matter: the search band around the mask.
cv::Mat refineWithin(const cv::Mat& mask, const cv::Mat& depth, int band_px,
                     const std::vector<float>& object_depths,
                     const DepthRefinementOptions& options) {
  const cv::Mat interior = shrunkMask(mask, options.core_erosion_px);
  cv::Mat blocker = fillBlocker(mask, band_px);
  const int num_values = fillRegions(interior, depth, blocker, options) + 1;
  cv::Mat refined = objectRegions(mask, blocker(cv::Rect(1, 1, mask.cols, mask.rows)), depth,
                                  num_values, object_depths, options);
  refined.setTo(255, (mask != 0) & (depth <= 0.0f));
  // Parts too thin to hold an interior seed (limbs, small objects) are kept as they are. The
  // interior grown back by a square reaches every pixel of a thick part, corners included.
  cv::Mat thick_parts;
  const int reach = 2 * options.core_erosion_px + 3;
  cv::dilate(interior, thick_parts,
             cv::getStructuringElement(cv::MORPH_RECT, cv::Size(reach, reach)));
  refined.setTo(255, (mask != 0) & (thick_parts == 0));
  return refined;
}

// The mask's bounding box grown by the band (and a margin that keeps the window's edge off the
// mask, where it would count as background), with its corner on the seed grid, so that the
// window holds everything the refinement looks at and seeds the same pixels as the whole image.
cv::Rect searchWindow(const cv::Mat& mask, int band_px, int seed_step_px) {
  const cv::Rect box = cv::boundingRect(mask);
  const int margin = band_px + 2;
  const int step = std::max(seed_step_px, 1);
  const int left = std::max(box.x - margin, 0) / step * step;
  const int top = std::max(box.y - margin, 0) / step * step;
  const int right = std::min(box.x + box.width + margin, mask.cols);
  const int bottom = std::min(box.y + box.height + margin, mask.rows);
  return {left, top, right - left, bottom - top};
}

// Every k-th pixel of every k-th row (the nearest pixel of a k times smaller image).
template <typename Pixel>
cv::Mat sampled(const cv::Mat& image, int k) {
  cv::Mat small((image.rows + k - 1) / k, (image.cols + k - 1) / k, image.type());
  for (int y = 0; y < small.rows; ++y) {
    const auto* row = image.ptr<Pixel>(y * k);
    auto* out = small.ptr<Pixel>(y);
    for (int x = 0; x < small.cols; ++x) out[x] = row[x * k];
  }
  return small;
}

// Each pixel of `small` repeated over k x k pixels of `out`, which is at most k times larger.
void repeated(const cv::Mat& small, int k, cv::Mat& out) {
  for (int y = 0; y < out.rows; ++y) {
    const auto* row = small.ptr<std::uint8_t>(y / k);
    auto* target = out.ptr<std::uint8_t>(y);
    for (int x = 0; x < out.cols; ++x) target[x] = row[x / k];
  }
}

// refineWithin at 1/downscale of the resolution, into `refined` (the window of the result): the
// pixel options scaled down with the images.
void refineDownscaled(const cv::Mat& mask, const cv::Mat& depth, int band_px,
                      const std::vector<float>& object_depths,
                      const DepthRefinementOptions& options, cv::Mat refined) {
  const int k = options.downscale;
  const auto scaledDown = [k](int px) { return std::max((px + k - 1) / k, 1); };
  DepthRefinementOptions scaled = options;
  scaled.core_erosion_px = scaledDown(options.core_erosion_px);
  scaled.seed_step_px = scaledDown(options.seed_step_px);
  repeated(refineWithin(sampled<std::uint8_t>(mask, k), sampled<float>(depth, k),
                        scaledDown(band_px), object_depths, scaled),
           k, refined);
}

}  // namespace

std::vector<float> objectDepths(const cv::Mat& mask, const cv::Mat& depth,
                                const DepthRefinementOptions& options) {
  if (mask.empty() || depth.empty()) return {};
  cv::Mat components;
  const int count = cv::connectedComponents(mask != 0, components, 8, CV_32S);
  std::vector<std::vector<float>> depths(count);
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      const int component = components.at<int>(y, x);
      const float z = depth.at<float>(y, x);
      if (component > 0 && z > 0.0f) depths[component].push_back(z);
    }
  }
  std::vector<float> medians;
  for (auto& values : depths) {
    if (static_cast<int>(values.size()) >= options.min_object_area_px) {
      medians.push_back(util::medianInPlace(values));
    }
  }
  return medians;
}

cv::Mat refineMaskByDepth(const cv::Mat& mask, const cv::Mat& depth, int band_px,
                          const std::vector<float>& object_depths,
                          const DepthRefinementOptions& options) {
  if (options.downscale < 1) {
    throw std::invalid_argument("refineMaskByDepth: downscale must be >= 1");
  }
  if (depth.empty() || mask.empty() || cv::countNonZero(mask) == 0) return mask.clone();
  const int band = std::max(band_px, 1);
  // On the downscaled grid too, the window's corner is a seed.
  const cv::Rect window =
      searchWindow(mask, band, std::max(options.seed_step_px, 1) * options.downscale);
  cv::Mat refined = cv::Mat::zeros(mask.size(), CV_8UC1);
  if (options.downscale > 1) {
    refineDownscaled(mask(window), depth(window), band, object_depths, options, refined(window));
  } else {
    refineWithin(mask(window), depth(window), band, object_depths, options).copyTo(refined(window));
  }
  return refined;
}

}  // namespace segslam::segmentation
