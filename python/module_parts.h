#pragma once

#include <pybind11/pybind11.h>

#include <vector>

#include "segslam/dense/dense_map.h"

// Each part of the `segslam` module adds its classes and functions (segslam_module.cc calls them
// in dependency order: a class must be known before a signature uses it).
namespace segslam::python {

namespace py = pybind11;

void bindCamera(py::module_& module);
void bindTrajectory(py::module_& module);
void bindDataset(py::module_& module);
void bindSegmenter(py::module_& module);
void bindDenseMap(py::module_& module);
void bindOccupancy(py::module_& module);
void bindSystem(py::module_& module);
void bindEvaluation(py::module_& module);

// A segslam.DenseMap (bindDenseMap) holding copies of the map's clouds.
py::object denseMapToNumpy(const dense::DenseMap& map);
// The map's objects alone (a list of segslam.MapObject): without the copy of every map point
// that denseMapToNumpy makes.
py::object mapObjectsToNumpy(const std::vector<dense::MapObject>& objects);

}  // namespace segslam::python
