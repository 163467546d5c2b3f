#include "segslam/synth/depth_noise.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <random>

#include "segslam/util/error.h"

namespace segslam::synth {

namespace {

std::uint16_t quantise(double z, double depth_factor) {
  const double raw = std::round(z * depth_factor);
  if (!(raw >= 1.0) || raw > std::numeric_limits<std::uint16_t>::max()) return 0;
  return static_cast<std::uint16_t>(raw);
}

bool isDiscontinuity(const cv::Mat& z, int row, int col) {
  const double centre = z.at<double>(row, col);
  const double threshold = kinectDiscontinuityThreshold(centre);
  constexpr int kOffsets[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  for (const auto& offset : kOffsets) {
    const int r = row + offset[0];
    const int c = col + offset[1];
    if (r < 0 || c < 0 || r >= z.rows || c >= z.cols) continue;
    const double neighbour = z.at<double>(r, c);
    if (neighbour <= 0.0 || std::abs(neighbour - centre) > threshold) return true;
  }
  return false;
}

void kinectRow(const cv::Mat& exact_z, int row, double depth_factor, std::uint64_t seed,
               cv::Mat& depth) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(row)};
  std::mt19937 rng(seq);
  std::normal_distribution<double> normal(0.0, 1.0);
  const auto* z = exact_z.ptr<double>(row);
  auto* out = depth.ptr<std::uint16_t>(row);
  for (int col = 0; col < exact_z.cols; ++col) {
    // Draw for every pixel so that each pixel's noise depends only on its position.
    const double noise = normal(rng);
    out[col] = 0;
    if (z[col] < kKinectMinDepth || z[col] > kKinectMaxDepth) continue;
    if (isDiscontinuity(exact_z, row, col)) continue;
    out[col] = quantise(z[col] + noise * kinectDepthSigma(z[col]), depth_factor);
  }
}

}  // namespace

DepthNoise depthNoiseFromName(const std::string& name) {
  if (name == "none") return DepthNoise::kNone;
  if (name == "kinect") return DepthNoise::kKinect;
  throw util::Error("unknown depth noise model '" + name + "' (known: none, kinect)");
}

double kinectDepthSigma(double z) { return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4); }

double kinectDiscontinuityThreshold(double z) { return 0.01 + 0.03 * z; }

cv::Mat depthImage(const cv::Mat& exact_z, DepthNoise model, double depth_factor,
                   std::uint64_t seed) {
  CV_Assert(exact_z.type() == CV_64FC1);
  cv::Mat depth(exact_z.size(), CV_16UC1);
  tbb::parallel_for(tbb::blocked_range<int>(0, exact_z.rows),
                    [&](const tbb::blocked_range<int>& rows) {
                      for (int row = rows.begin(); row != rows.end(); ++row) {
                        if (model == DepthNoise::kKinect) {
                          kinectRow(exact_z, row, depth_factor, seed, depth);
                          continue;
                        }
                        const auto* z = exact_z.ptr<double>(row);
                        auto* out = depth.ptr<std::uint16_t>(row);
                        for (int col = 0; col < exact_z.cols; ++col)
                          out[col] = quantise(z[col], depth_factor);
                      }
                    });
  return depth;
}

}  // namespace segslam::synth
