#include "numpy_arrays.h"

#include <fmt/format.h>

#include <memory>

namespace segslam::python {

namespace {

// A rotation block this far from orthonormal is no rotation (float32 poses stay well within).
constexpr double kOrthonormalTolerance = 1e-4;

}  // namespace

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) {
    text += fmt::format("{}{}", i > 0 ? ", " : "", array.shape(i));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

std::string dtypeName(const py::dtype& dtype) { return dtype.attr("name").cast<std::string>(); }

void requireDtype(const py::array& array, const py::dtype& dtype, std::string_view name) {
  if (!array.dtype().is(dtype)) {
    throw py::type_error(fmt::format("{} must be a numpy array of dtype {}, not {}", name,
                                     dtypeName(dtype), dtypeName(array.dtype())));
  }
}

void requireDimensions(const py::array& array, py::ssize_t dims, std::string_view shape,
                       std::string_view name) {
  if (array.ndim() != dims) {
    throw py::value_error(
        fmt::format("{} must have shape {}, not {}", name, shape, shapeText(array)));
  }
}

py::array contiguous(const py::array& array) {
  if (array.flags() & py::array::c_style) return array;
  return py::array::ensure(array, py::array::c_style);
}

cv::Mat matView(const py::array& array, int cv_type) {
  const int rows = static_cast<int>(array.shape(0));
  const int cols = array.ndim() > 1 ? static_cast<int>(array.shape(1)) : 1;
  return cv::Mat(rows, cols, cv_type, const_cast<void*>(array.data()));
}

py::array toNumpy(const cv::Mat& image) {
  const cv::Mat owned = image.isContinuous() ? image : image.clone();
  auto* keeper = new cv::Mat(owned);
  const py::capsule free_when_done(keeper, [](void* mat) { delete static_cast<cv::Mat*>(mat); });
  std::vector<py::ssize_t> shape = {owned.rows, owned.cols};
  if (owned.channels() > 1) shape.push_back(owned.channels());
  const auto dtype = [&] {
    switch (owned.depth()) {
      case CV_8U:
        return py::dtype::of<std::uint8_t>();
      case CV_16U:
        return py::dtype::of<std::uint16_t>();
      case CV_32F:
        return py::dtype::of<float>();
      default:
        return py::dtype::of<double>();
    }
  }();
  return py::array(dtype, shape, owned.data, free_when_done);
}

geometry::Pose poseFromNumpy(const py::array& array, std::string_view name) {
  requireDtype(array, py::dtype::of<double>(), name);
  if (array.ndim() != 2 || array.shape(0) != 4 || array.shape(1) != 4) {
    throw py::value_error(fmt::format("{} must have shape (4, 4), not {}", name, shapeText(array)));
  }
  const auto values = py::array_t<double>::ensure(array).unchecked<2>();
  Eigen::Matrix4d matrix;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) matrix(r, c) = values(r, c);
  }
  if (!matrix.allFinite()) throw py::value_error(fmt::format("{} has NaN or inf", name));
  if (!matrix.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1))) {
    throw py::value_error(fmt::format("{}'s last row must be [0, 0, 0, 1]", name));
  }
  const Eigen::Matrix3d rotation = matrix.topLeftCorner<3, 3>();
  if (!(rotation * rotation.transpose())
           .isApprox(Eigen::Matrix3d::Identity(), kOrthonormalTolerance) ||
      rotation.determinant() < 0) {
    throw py::value_error(fmt::format("{}'s rotation block is not a rotation", name));
  }
  geometry::Pose pose = geometry::Pose::Identity();
  pose.matrix() = matrix;
  return pose;
}

py::array_t<double> poseToNumpy(const geometry::Pose& pose) {
  py::array_t<double> array({4, 4});
  auto values = array.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) values(r, c) = pose.matrix()(r, c);
  }
  return array;
}

}  // namespace segslam::python
