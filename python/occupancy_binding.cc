#include <octomap/OcTree.h>
#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include <memory>

#include "module_parts.h"
#include "segslam/occupancy/occupancy_map.h"

namespace segslam::python {

namespace {

// A run's occupancy map (map/occupancy.bt, or any OctoMap .bt) for Python.
class OccupancyFile {
 public:
  explicit OccupancyFile(const std::filesystem::path& path) : tree_(occupancy::readOctree(path)) {}

  [[nodiscard]] double resolution() const { return tree_->getResolution(); }
  [[nodiscard]] py::array_t<double> occupied() const {
    return centres(occupancy::voxelCentres(*tree_, true));
  }
  [[nodiscard]] py::array_t<double> free() const {
    return centres(occupancy::voxelCentres(*tree_, false));
  }

  // Per point: 1 occupied, 0 free, -1 unknown.
  [[nodiscard]] py::array_t<std::int8_t> stateAt(
      const py::array_t<double, py::array::c_style | py::array::forcecast>& points) const {
    if (points.ndim() != 2 || points.shape(1) != 3) {
      throw py::value_error("points must have the shape (N, 3)");
    }
    py::array_t<std::int8_t> states(points.shape(0));
    auto out = states.mutable_unchecked<1>();
    const auto in = points.unchecked<2>();
    for (py::ssize_t i = 0; i < points.shape(0); ++i) {
      const auto state = occupancy::stateAt(*tree_, {in(i, 0), in(i, 1), in(i, 2)});
      out(i) = state == occupancy::VoxelState::kOccupied ? 1
               : state == occupancy::VoxelState::kFree   ? 0
                                                         : -1;
    }
    return states;
  }

 private:
  static py::array_t<double> centres(const std::vector<Eigen::Vector3d>& voxels) {
    py::array_t<double> array({static_cast<py::ssize_t>(voxels.size()), py::ssize_t{3}});
    auto out = array.mutable_unchecked<2>();
    for (std::size_t i = 0; i < voxels.size(); ++i) {
      for (int k = 0; k < 3; ++k) out(static_cast<py::ssize_t>(i), k) = voxels[i][k];
    }
    return array;
  }

  std::unique_ptr<octomap::OcTree> tree_;
};

}  // namespace

void bindOccupancy(py::module_& module) {
  py::class_<OccupancyFile>(module, "OccupancyMap",
                            "An occupancy map as `segslam run` writes it (map/occupancy.bt, "
                            "OctoMap's binary format): free, occupied and unknown space.")
      .def(py::init<const std::filesystem::path&>(), py::arg("path"),
           "Reads an OctoMap .bt file; ValueError naming it when it cannot be read.")
      .def_property_readonly("resolution", &OccupancyFile::resolution, "Voxel edge, metres.")
      .def_property_readonly("occupied", &OccupancyFile::occupied,
                             "float64 (N, 3): centres of the occupied voxels, world frame.")
      .def_property_readonly("free", &OccupancyFile::free,
                             "float64 (M, 3): centres of the free voxels.")
      .def("state", &OccupancyFile::stateAt, py::arg("points"),
           "int8 (N,) for float64 (N, 3) points: 1 occupied, 0 free, -1 unknown.");
}

}  // namespace segslam::python
