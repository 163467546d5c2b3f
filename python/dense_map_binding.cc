#include <fmt/format.h>
#include <pybind11/eigen.h>
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

// An object of the map, as map/objects.json describes it, with its points.
struct MapObject {
  std::string id;
  std::string label;
  int instance = 0;
  bool dynamic = false;
  double confidence = 0.0;
  int keyframes = 0;
  Cloud points;
  Eigen::Vector3f centroid;
  Eigen::Vector3f bbox_min;
  Eigen::Vector3f bbox_max;
  Eigen::Vector3f box_centre;
  Eigen::Vector3f box_extent;
  Eigen::Matrix3f box_axes;
};

struct DenseMap {
  double voxel_size = 0.0;
  Cloud static_points;
  Cloud dynamic_points;
  std::vector<MapObject> objects;
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

MapObject toMapObject(const dense::MapObject& object) {
  return {object.id,         object.label,     object.instance,        object.dynamic,
          object.confidence, object.keyframes, toCloud(object.points), object.centroid,
          object.bbox_min,   object.bbox_max,  object.box.centre,      object.box.extent,
          object.box.axes};
}

void bindMapObject(py::module_& module) {
  py::class_<MapObject>(module, "MapObject",
                        "An object of the dense map (as map/objects.json of `segslam run`).")
      .def_readonly("id", &MapObject::id, "'<label>_<instance>', e.g. 'chair_1'.")
      .def_readonly("label", &MapObject::label, "One of segslam.SEMANTIC_CLASSES.")
      .def_readonly("instance", &MapObject::instance, "1, 2, ... per label.")
      .def_readonly("dynamic", &MapObject::dynamic,
                    "A track of something that moved (a walking person), not a static object.")
      .def_readonly("confidence", &MapObject::confidence,
                    "Share of the keyframes that saw it that gave it its label.")
      .def_readonly("keyframes", &MapObject::keyframes, "Keyframes that saw it.")
      .def_readonly("points", &MapObject::points)
      .def_readonly("centroid", &MapObject::centroid, "float32 (3,), world frame.")
      .def_readonly("bbox_min", &MapObject::bbox_min, "float32 (3,): axis-aligned bounds.")
      .def_readonly("bbox_max", &MapObject::bbox_max)
      .def_readonly("box_centre", &MapObject::box_centre, "Oriented box: float32 (3,).")
      .def_readonly("box_extent", &MapObject::box_extent, "Full side lengths along box_axes.")
      .def_readonly("box_axes", &MapObject::box_axes, "float32 (3, 3): the box's axes as columns.")
      .def("__repr__", [](const MapObject& object) {
        return fmt::format("MapObject({}, {} points{})", object.id, object.points.points.shape(0),
                           object.dynamic ? ", dynamic" : "");
      });
}

std::vector<std::string> semanticClassNames() {
  return {core::kSemanticClassNames.begin(), core::kSemanticClassNames.end()};
}

}  // namespace

py::object mapObjectsToNumpy(const std::vector<dense::MapObject>& objects) {
  std::vector<MapObject> arrays;
  arrays.reserve(objects.size());
  for (const auto& object : objects) arrays.push_back(toMapObject(object));
  return py::cast(std::move(arrays));
}

py::object denseMapToNumpy(const dense::DenseMap& map) {
  DenseMap arrays{map.voxel_size, toCloud(map.static_points), toCloud(map.dynamic_points), {}};
  for (const auto& object : map.objects) arrays.objects.push_back(toMapObject(object));
  return py::cast(std::move(arrays));
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
  bindMapObject(module);
  py::class_<DenseMap>(module, "DenseMap",
                       "The dense map of a run's keyframes, in the trajectory's world frame.")
      .def_readonly("voxel_size", &DenseMap::voxel_size, "Metres.")
      .def_readonly("static_points", &DenseMap::static_points)
      .def_readonly("dynamic_points", &DenseMap::dynamic_points,
                    "Where dynamic objects were seen (to check the masks).")
      .def_readonly("objects", &DenseMap::objects,
                    "The objects: static ones, then the tracks of dynamic ones.");
}

}  // namespace segslam::python
