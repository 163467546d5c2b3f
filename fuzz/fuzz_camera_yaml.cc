// io::parseCameraYaml either throws util::Error or returns camera settings that pass validation.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "segslam/io/camera_config.h"
#include "segslam/util/error.h"

namespace {

using segslam::fuzz::check;

void checkCamera(const segslam::core::Camera& camera) {
  check(camera.width > 0 && camera.height > 0, "image size is positive");
  check(camera.fx > 0.0 && camera.fy > 0.0 && std::isfinite(camera.fx) && std::isfinite(camera.fy),
        "focal lengths are positive and finite");
  check(std::isfinite(camera.cx) && std::isfinite(camera.cy), "principal point is finite");
  check(camera.depth_factor > 0.0 && std::isfinite(camera.depth_factor),
        "depth factor is positive and finite");
  check(camera.fps > 0.0 && std::isfinite(camera.fps), "frame rate is positive and finite");
  for (double d : camera.distortion) check(std::isfinite(d), "distortion is finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    checkCamera(segslam::io::parseCameraYaml(text, "fuzz.yaml"));
  } catch (const segslam::util::Error&) {
    // Rejected input, with a message: the expected outcome for most inputs.
  }
  return 0;
}
