#include "frame_arrays.h"

#include <fmt/format.h>

#include <limits>
#include <opencv2/imgproc.hpp>

#include "numpy_arrays.h"

namespace segslam::python {

namespace {

void requireCameraSize(const py::array& array, const core::Camera& camera, std::string_view name) {
  if (array.shape(0) != camera.height || array.shape(1) != camera.width) {
    throw py::value_error(fmt::format("{} is {}x{} pixels but the camera's images are {}x{}", name,
                                      array.shape(1), array.shape(0), camera.width, camera.height));
  }
}

cv::Mat rgbView(const py::array& rgb, const core::Camera& camera, std::vector<py::array>& keep) {
  requireDtype(rgb, py::dtype::of<std::uint8_t>(), "rgb");
  if (rgb.ndim() != 3 || rgb.shape(2) != 3) {
    throw py::value_error(
        fmt::format("rgb must have shape (height, width, 3), not {}", shapeText(rgb)));
  }
  requireCameraSize(rgb, camera, "rgb");
  keep.push_back(contiguous(rgb));
  return matView(keep.back(), CV_8UC3);
}

cv::Mat depthView(const py::array& depth, const core::Camera& camera,
                  std::vector<py::array>& keep) {
  const bool raw = depth.dtype().is(py::dtype::of<std::uint16_t>());
  if (!raw && !depth.dtype().is(py::dtype::of<float>())) {
    throw py::type_error(fmt::format(
        "depth must be a numpy array of dtype uint16 (raw units) or float32 (metres), not {}",
        dtypeName(depth.dtype())));
  }
  requireDimensions(depth, 2, "(height, width)", "depth");
  requireCameraSize(depth, camera, "depth");
  keep.push_back(contiguous(depth));
  return matView(keep.back(), raw ? CV_16UC1 : CV_32FC1);
}

cv::Mat maskView(const py::object& mask, const core::Camera& camera, std::vector<py::array>& keep) {
  if (mask.is_none()) return {};
  if (!py::isinstance<py::array>(mask)) {
    throw py::type_error("mask must be None or a numpy array of dtype uint8 or bool");
  }
  const auto array = mask.cast<py::array>();
  if (!array.dtype().is(py::dtype::of<std::uint8_t>()) &&
      !array.dtype().is(py::dtype::of<bool>())) {
    throw py::type_error(fmt::format("mask must be a numpy array of dtype uint8 or bool, not {}",
                                     dtypeName(array.dtype())));
  }
  requireDimensions(array, 2, "(height, width)", "mask");
  requireCameraSize(array, camera, "mask");
  keep.push_back(contiguous(array));
  return matView(keep.back(), CV_8UC1);
}

// A copy in metres where every value that is no depth (NaN, inf, negative) is 0, in OpenCV's
// vectorised passes: a plain loop over the pixels cost 0.65 ms per 640x480 frame, most of the
// module's per-frame overhead (bench/python_overhead.py).
cv::Mat cleanMetres(const cv::Mat& metres) {
  cv::Mat clean;
  cv::threshold(metres, clean, 0.0, 0.0, cv::THRESH_TOZERO);  // negative (and NaN) to 0
  cv::threshold(clean, clean, std::numeric_limits<float>::max(), 0.0, cv::THRESH_TOZERO_INV);
  cv::patchNaNs(clean, 0.0);
  return clean;
}

}  // namespace

FrameViews checkFrame(const py::array& rgb, const py::array& depth, const py::object& mask,
                      const core::Camera& camera) {
  FrameViews views;
  views.rgb = rgbView(rgb, camera, views.arrays);
  views.depth = depthView(depth, camera, views.arrays);
  views.mask = maskView(mask, camera, views.arrays);
  return views;
}

io::RgbdFrame toRgbdFrame(double timestamp, const FrameViews& views, const core::Camera& camera) {
  io::RgbdFrame frame;
  frame.timestamp = timestamp;
  cv::cvtColor(views.rgb, frame.rgb, cv::COLOR_RGB2BGR);
  if (views.depth.type() == CV_16UC1) {
    views.depth.convertTo(frame.depth, CV_32F, 1.0 / camera.depth_factor);
  } else {
    frame.depth = cleanMetres(views.depth);
  }
  frame.mask = views.mask;
  return frame;
}

}  // namespace segslam::python
