#pragma once

// Synthetic cameras, points and noisy observations for the optimiser tests (header-only, never
// linked into the library).

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "segslam/geometry/pose.h"
#include "segslam/optim/reprojection.h"

namespace segslam::optim::testing {

inline constexpr int kImageWidth = 640;
inline constexpr int kImageHeight = 480;
inline constexpr double kScaleFactor = 1.2;  // pyramid scale: sigma = 1.2^level pixels
inline constexpr int kNumLevels = 4;

inline double degrees(double radians) { return radians * 180.0 / M_PI; }

inline bool isInImage(const Eigen::Vector2d& pixel) {
  return pixel.x() >= 0.0 && pixel.x() < kImageWidth && pixel.y() >= 0.0 &&
         pixel.y() < kImageHeight;
}

// World point that projects to a uniformly random pixel of camera T_cw at a depth in [near, far].
inline Eigen::Vector3d randomVisiblePoint(std::mt19937& rng, const StereoIntrinsics& k,
                                          const geometry::Pose& T_cw, double near, double far) {
  std::uniform_real_distribution<double> u(0.0, kImageWidth);
  std::uniform_real_distribution<double> v(0.0, kImageHeight);
  std::uniform_real_distribution<double> depth(near, far);
  const double z = depth(rng);
  const Eigen::Vector3d p_c((u(rng) - k.cx) * z / k.fx, (v(rng) - k.cy) * z / k.fy, z);
  return T_cw.inverse() * p_c;
}

// Observation of p_w by camera T_cw: Gaussian pixel noise of the keypoint's pyramid level on u
// and v (information matches it) and, when `with_depth`, a depth error of 1 % carried into u_r.
inline RgbdObservation noisyObservation(std::mt19937& rng, const StereoIntrinsics& k,
                                        const geometry::Pose& T_cw, const Eigen::Vector3d& p_w,
                                        bool with_depth) {
  constexpr double kDepthNoiseRatio = 0.01;
  std::uniform_int_distribution<int> level(0, kNumLevels - 1);
  const double sigma = std::pow(kScaleFactor, level(rng));
  std::normal_distribution<double> noise(0.0, 1.0);
  const Eigen::Vector3d p_c = T_cw * p_w;
  const Eigen::Vector3d predicted = predictMeasurement(k, p_c);
  RgbdObservation observation;
  observation.pixel = {predicted.x() + sigma * noise(rng), predicted.y() + sigma * noise(rng)};
  // u_r = u - bf / z, so a depth error dz moves it by bf dz / z^2.
  const double right_u_sigma = k.bf * kDepthNoiseRatio / p_c.z();
  observation.right_u = with_depth ? predicted.z() + right_u_sigma * noise(rng) : -1.0;
  observation.information = 1.0 / (sigma * sigma);
  return observation;
}

// A gross mismatch: a random pixel with a random depth (when `with_depth`).
inline RgbdObservation randomObservation(std::mt19937& rng, const StereoIntrinsics& k,
                                         bool with_depth) {
  std::uniform_real_distribution<double> u(0.0, kImageWidth);
  std::uniform_real_distribution<double> v(0.0, kImageHeight);
  std::uniform_real_distribution<double> depth(0.5, 8.0);
  RgbdObservation observation;
  observation.pixel = {u(rng), v(rng)};
  observation.right_u = with_depth ? observation.pixel.x() - k.bf / depth(rng) : -1.0;
  return observation;
}

// `pose` moved by `translation_m` metres along a random direction and rotated by `angle_rad`
// about a random axis.
inline geometry::Pose perturbedPose(std::mt19937& rng, const geometry::Pose& pose,
                                    double translation_m, double angle_rad) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::Vector3d direction =
      Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
  const Eigen::Vector3d axis = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
  geometry::Pose delta = geometry::Pose::Identity();
  delta.linear() = Eigen::AngleAxisd(angle_rad, axis).toRotationMatrix();
  delta.translation() = translation_m * direction;
  return delta * pose;
}

inline double translationError(const geometry::Pose& estimate, const geometry::Pose& truth) {
  return (estimate.inverse().translation() - truth.inverse().translation()).norm();
}

inline double rotationErrorDegrees(const geometry::Pose& estimate, const geometry::Pose& truth) {
  return degrees(geometry::rotationAngleAccurate(estimate * truth.inverse()));
}

}  // namespace segslam::optim::testing
