#pragma once

#include <pybind11/numpy.h>

#include <opencv2/core.hpp>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/io/tum_dataset.h"

// One frame's images as Python hands them over: checked against the camera while the GIL is
// held, copied into the core's layout while it is not.
namespace segslam::python {

namespace py = pybind11;

// Views of the caller's arrays (no copy yet). Destroy it with the GIL held: it keeps the arrays.
struct FrameViews {
  std::vector<py::array> arrays;
  cv::Mat rgb;    // CV_8UC3, RGB
  cv::Mat depth;  // CV_16UC1 raw units or CV_32FC1 metres
  cv::Mat mask;   // CV_8UC1 (uint8 or bool), non-zero = dynamic; empty = none
};

// rgb: HxWx3 uint8; depth: HxW uint16 (raw, the camera's depth factor) or float32 (metres);
// mask: None or HxW uint8 / bool; H and W the camera's. TypeError for a wrong dtype, ValueError
// for a wrong shape or size.
FrameViews checkFrame(const py::array& rgb, const py::array& depth, const py::object& mask,
                      const core::Camera& camera);

// The frame in the core's layout, in fresh buffers: BGR, depth in metres as the dataset reader
// converts it (raw / depth_factor), where NaN, infinite and negative depths become 0 (no
// measurement). Needs no GIL.
io::RgbdFrame toRgbdFrame(double timestamp, const FrameViews& views, const core::Camera& camera);

}  // namespace segslam::python
