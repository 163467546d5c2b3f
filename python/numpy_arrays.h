#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <opencv2/core.hpp>
#include <string>
#include <string_view>

#include "segslam/geometry/pose.h"

// Checked conversions between numpy arrays and the core's OpenCV and Eigen types. Every check
// raises TypeError (wrong dtype) or ValueError (wrong shape or values) naming the argument, so
// that bad input never reaches the C++ core.
namespace segslam::python {

namespace py = pybind11;

// "(480, 640, 3)": the array's shape as numpy writes it.
std::string shapeText(const py::array& array);
// "uint8", "float32", ...
std::string dtypeName(const py::dtype& dtype);
// Raises TypeError unless `array` holds exactly `dtype`.
void requireDtype(const py::array& array, const py::dtype& dtype, std::string_view name);
// Raises ValueError unless `array` has `dims` dimensions.
void requireDimensions(const py::array& array, py::ssize_t dims, std::string_view shape,
                       std::string_view name);

// The array itself when it is C-contiguous, else a C-contiguous copy: cv::Mat has row strides
// only.
py::array contiguous(const py::array& array);
// A cv::Mat of `cv_type` over a C-contiguous 2-D or 3-D array's data, no copy: keep the array
// alive while the view is used.
cv::Mat matView(const py::array& array, int cv_type);
// A numpy array over the image's pixels, no copy: it keeps the cv::Mat's buffer alive.
py::array toNumpy(const cv::Mat& image);

// 4x4 float64 rigid transform; ValueError when the last row is not 0 0 0 1 or the rotation is
// not orthonormal.
geometry::Pose poseFromNumpy(const py::array& array, std::string_view name);
py::array_t<double> poseToNumpy(const geometry::Pose& pose);

}  // namespace segslam::python
