#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "module_parts.h"
#include "segslam/core/semantic_class.h"
#include "segslam/dense/dense_map.h"

namespace segslam::python {

namespace {

// A labelled cloud as numpy arrays of equal length.
struct Cloud {
  py::array_t<float> points;
  py::array_t<std::uint8_t> colours;
  py::array_t<std::uint8_t> labels;
  py::array_t<std::uint16_t> instances;
};

struct DenseMap {
  double voxel_size = 0.0;
  Cloud static_points;
  Cloud dynamic_points;
};

Cloud toCloud(const dense::LabelledCloud& cloud) {
  const auto n = static_cast<py::ssize_t>(cloud.size());
  Cloud arrays{py::array_t<float>({n, py::ssize_t{3}}),
               py::array_t<std::uint8_t>({n, py::ssize_t{3}}), py::array_t<std::uint8_t>(n),
               py::array_t<std::uint16_t>(n)};
  auto points = arrays.points.mutable_unchecked<2>();
  auto colours = arrays.colours.mutable_unchecked<2>();
  auto labels = arrays.labels.mutable_unchecked<1>();
  auto instances = arrays.instances.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    for (py::ssize_t c = 0; c < 3; ++c) {
      points(i, c) = cloud.points[k][c];
      colours(i, c) = cloud.colours[k][static_cast<std::size_t>(c)];
    }
    labels(i) = cloud.labels[k];
    instances(i) = cloud.instances[k];
  }
  return arrays;
}

std::vector<std::string> semanticClassNames() {
  return {core::kSemanticClassNames.begin(), core::kSemanticClassNames.end()};
}

}  // namespace

py::object denseMapToNumpy(const dense::DenseMap& map) {
  return py::cast(
      DenseMap{map.voxel_size, toCloud(map.static_points), toCloud(map.dynamic_points)});
}

void bindDenseMap(py::module_& module) {
  module.attr("SEMANTIC_CLASSES") = semanticClassNames();
  py::class_<Cloud>(module, "Cloud", "A coloured, labelled point cloud as numpy arrays.")
      .def_readonly("points", &Cloud::points, "float32 (N, 3), metres, world frame.")
      .def_readonly("colours", &Cloud::colours, "uint8 (N, 3), RGB.")
      .def_readonly("labels", &Cloud::labels,
                    "uint8 (N,): index into segslam.SEMANTIC_CLASSES (0 = none).")
      .def_readonly("instances", &Cloud::instances, "uint16 (N,): instance id, 0 = none.")
      .def("__len__", [](const Cloud& cloud) { return cloud.points.shape(0); })
      .def("__repr__", [](const Cloud& cloud) {
        return fmt::format("Cloud({} points)", cloud.points.shape(0));
      });
  py::class_<DenseMap>(module, "DenseMap",
                       "The dense map of a run's keyframes, in the trajectory's world frame.")
      .def_readonly("voxel_size", &DenseMap::voxel_size, "Metres.")
      .def_readonly("static_points", &DenseMap::static_points)
      .def_readonly("dynamic_points", &DenseMap::dynamic_points,
                    "Where dynamic objects were seen (to check the masks).");
}

}  // namespace segslam::python
