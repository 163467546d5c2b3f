// io::parseTumTrajectory either throws util::Error or returns a usable trajectory: finite,
// strictly increasing timestamps and proper rotations.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/util/error.h"

namespace {

using segslam::fuzz::check;

void checkTrajectory(const segslam::core::Trajectory& trajectory) {
  check(!trajectory.empty(), "a parsed trajectory has poses");
  double previous = -INFINITY;
  for (const auto& pose : trajectory.poses()) {
    check(std::isfinite(pose.timestamp) && pose.timestamp > previous,
          "timestamps are finite and increase");
    check(pose.T_wc.translation().allFinite(), "translations are finite");
    const Eigen::Matrix3d rotation = pose.T_wc.linear();
    check((rotation.transpose() * rotation).isIdentity(1e-9), "rotations are orthonormal");
    check(std::abs(rotation.determinant() - 1.0) < 1e-9, "rotations are proper");
    previous = pose.timestamp;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    checkTrajectory(segslam::io::parseTumTrajectory(text, "fuzz.txt"));
  } catch (const segslam::util::Error&) {
    // Rejected input, with a message: the expected outcome for most inputs.
  }
  return 0;
}
