#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

namespace segslam::core {

// Pinhole RGB-D camera with Brown-Conrady distortion (k1 k2 p1 p2 k3, OpenCV order).
// Depth images are registered to the colour camera; metres = raw value / depth_factor.
struct Camera {
  std::string name = "custom";
  int width = 640;
  int height = 480;
  double fx = 525.0;
  double fy = 525.0;
  double cx = 319.5;
  double cy = 239.5;
  std::array<double, 5> distortion{0.0, 0.0, 0.0, 0.0, 0.0};
  double depth_factor = 5000.0;
  double fps = 30.0;
  // Seconds from the first image row's exposure to the last's (rolling shutter); 0 for a global
  // shutter; negative when the last row is read first (a sensor mounted upside down whose images
  // are turned upright, or frames played backwards). A moving camera sees each row at another
  // moment: tracking moves keypoints to the middle row's moment before it uses them
  // (map::Frame::compensateRollingShutter).
  double rolling_shutter_readout_s = 0.0;

  [[nodiscard]] bool hasDistortion() const;
  // Pixel (u, v) at depth z (metres) to a camera-frame point, ignoring distortion.
  [[nodiscard]] Eigen::Vector3d backProject(double u, double v, double z) const;
  // Camera-frame point to pixel, ignoring distortion.
  [[nodiscard]] Eigen::Vector2d project(const Eigen::Vector3d& p_c) const;
};

}  // namespace segslam::core
