#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace segslam::synth {

enum class DepthNoise { kNone, kKinect };

// "none" or "kinect"; anything else throws util::Error.
DepthNoise depthNoiseFromName(const std::string& name);

inline constexpr double kKinectMinDepth = 0.4;  // metres
inline constexpr double kKinectMaxDepth = 8.0;

// Standard deviation (metres) of the kinect model's axial noise at depth z:
// 0.0012 + 0.0019 * (z - 0.4)^2.
double kinectDepthSigma(double z);

// A 4-neighbour whose depth differs by more than this (or that has none) makes a pixel a depth
// discontinuity, where the kinect model reports no depth.
double kinectDiscontinuityThreshold(double z);

// The stored depth image (CV_16UC1, round(z * depth_factor), 0 = no depth) of the exact depth
// `exact_z` (CV_64FC1, metres along the optical axis, 0 = nothing hit).
// - kNone: exact z, only quantised.
// - kKinect: z + N(0, kinectDepthSigma(z)), no depth below kKinectMinDepth, beyond
//   kKinectMaxDepth and at depth discontinuities. The noise of row r comes from a generator seeded
//   with (seed, r), so the result does not depend on the number of threads.
// Depths too large for 16 bits are reported as no depth.
cv::Mat depthImage(const cv::Mat& exact_z, DepthNoise model, double depth_factor,
                   std::uint64_t seed);

}  // namespace segslam::synth
