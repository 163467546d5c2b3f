// Smooths a tracked camera trajectory (TUM format) with the given noise model, so that the
// model's settings can be compared on runs already made: segslam_bench_trajectory_smoothing
// TRACKED OUT [position_sigma_m rotation_sigma_deg acceleration_m_s2 angular_acceleration_rad_s2]
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "segslam/io/trajectory_io.h"
#include "segslam/optim/trajectory_smoother.h"

int main(int argc, char** argv) {
  if (argc != 3 && argc != 7) {
    std::fprintf(stderr,
                 "usage: %s TRACKED OUT [position_sigma_m rotation_sigma_deg acceleration_m_s2 "
                 "angular_acceleration_rad_s2]\n",
                 argv[0]);
    return 2;
  }
  try {
    segslam::optim::TrajectorySmoothingOptions options;
    if (argc == 7) {
      options.position_sigma_m = std::atof(argv[3]);
      options.rotation_sigma_deg = std::atof(argv[4]);
      options.acceleration_m_s2 = std::atof(argv[5]);
      options.angular_acceleration_rad_s2 = std::atof(argv[6]);
    }
    const auto tracked = segslam::io::readTumTrajectory(argv[1]);
    segslam::io::writeTumTrajectory(argv[2], segslam::optim::smoothTrajectory(tracked, options),
                                    "smoothed by segslam_bench_trajectory_smoothing");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
