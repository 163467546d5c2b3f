#include <fmt/format.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>

#include "module_parts.h"
#include "numpy_arrays.h"
#include "segslam/core/trajectory.h"
#include "segslam/io/ground_truth_frame.h"
#include "segslam/io/trajectory_io.h"

namespace segslam::python {

namespace {

// ValueError naming the first pose whose timestamp does not increase.
void requireIncreasing(const py::detail::unchecked_reference<double, 1>& stamps) {
  for (py::ssize_t i = 0; i < stamps.shape(0); ++i) {
    if (!std::isfinite(stamps(i))) {
      throw py::value_error(fmt::format("timestamps[{}] is not finite", i));
    }
    if (i > 0 && !(stamps(i) > stamps(i - 1))) {
      throw py::value_error(
          fmt::format("timestamps must increase strictly: timestamps[{}] = {} follows {}", i,
                      stamps(i), stamps(i - 1)));
    }
  }
}

core::Trajectory trajectoryFromNumpy(const py::array& timestamps, const py::array& poses) {
  requireDtype(timestamps, py::dtype::of<double>(), "timestamps");
  requireDtype(poses, py::dtype::of<double>(), "poses");
  requireDimensions(timestamps, 1, "(N,)", "timestamps");
  if (poses.ndim() != 3 || poses.shape(0) != timestamps.shape(0) || poses.shape(1) != 4 ||
      poses.shape(2) != 4) {
    throw py::value_error(fmt::format("poses must have shape ({}, 4, 4) for {} timestamps",
                                      timestamps.shape(0), timestamps.shape(0)));
  }
  const auto stamps = py::array_t<double>::ensure(timestamps).unchecked<1>();
  requireIncreasing(stamps);
  const py::array all_poses = contiguous(poses);
  std::vector<core::StampedPose> stamped;
  stamped.reserve(static_cast<std::size_t>(stamps.shape(0)));
  for (py::ssize_t i = 0; i < stamps.shape(0); ++i) {
    const py::array pose = all_poses[py::int_(i)];
    stamped.push_back({stamps(i), poseFromNumpy(pose, fmt::format("poses[{}]", i))});
  }
  return core::Trajectory(std::move(stamped));
}

py::array_t<double> timestampsOf(const core::Trajectory& trajectory) {
  py::array_t<double> stamps(static_cast<py::ssize_t>(trajectory.size()));
  auto values = stamps.mutable_unchecked<1>();
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    values(static_cast<py::ssize_t>(i)) = trajectory[i].timestamp;
  }
  return stamps;
}

py::array_t<double> posesOf(const core::Trajectory& trajectory) {
  py::array_t<double> poses(
      {static_cast<py::ssize_t>(trajectory.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto values = poses.mutable_unchecked<3>();
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Eigen::Matrix4d& matrix = trajectory[i].T_wc.matrix();
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) values(static_cast<py::ssize_t>(i), r, c) = matrix(r, c);
    }
  }
  return poses;
}

py::array_t<double> positionsOf(const core::Trajectory& trajectory) {
  py::array_t<double> positions({static_cast<py::ssize_t>(trajectory.size()), py::ssize_t{3}});
  auto values = positions.mutable_unchecked<2>();
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Eigen::Vector3d t = trajectory[i].T_wc.translation();
    for (int k = 0; k < 3; ++k) values(static_cast<py::ssize_t>(i), k) = t[k];
  }
  return positions;
}

}  // namespace

void bindTrajectory(py::module_& module) {
  py::class_<core::Trajectory>(
      module, "Trajectory",
      "Camera poses (camera-to-world, the TUM convention) at strictly increasing timestamps.")
      .def(py::init(&trajectoryFromNumpy), py::arg("timestamps"), py::arg("poses"),
           "From float64 arrays: timestamps (N,) in seconds, poses (N, 4, 4) rigid transforms.")
      .def_static(
          "read_tum",
          [](const std::filesystem::path& path, const std::string& frame) {
            const auto ground_truth_frame = io::requireGroundTruthFrame(frame);
            const py::gil_scoped_release unlocked;
            return io::toCameraPoses(io::readTumTrajectory(path), ground_truth_frame);
          },
          py::arg("path"), py::kw_only(), py::arg("frame") = "camera",
          "Reads a TUM trajectory file (`t tx ty tz qx qy qz qw` per line). frame: what it holds "
          "poses of; 'bonn-markers' (a Bonn RGB-D Dynamic groundtruth.txt) gives the camera's "
          "poses by the dataset's transform.")
      .def(
          "write_tum",
          [](const core::Trajectory& trajectory, const std::filesystem::path& path) {
            const py::gil_scoped_release unlocked;
            io::writeTumTrajectory(path, trajectory);
          },
          py::arg("path"), "Writes a TUM trajectory file (timestamps to 1 us, values to 1e-9).")
      .def_property_readonly("timestamps", &timestampsOf, "float64 (N,), seconds.")
      .def_property_readonly("poses", &posesOf, "float64 (N, 4, 4), camera-to-world.")
      .def_property_readonly("positions", &positionsOf, "float64 (N, 3): the camera centres.")
      .def("__len__", &core::Trajectory::size)
      .def("__repr__", [](const core::Trajectory& trajectory) {
        return trajectory.empty()
                   ? std::string("Trajectory(0 poses)")
                   : fmt::format("Trajectory({} poses, {:.6f} s to {:.6f} s)", trajectory.size(),
                                 trajectory[0].timestamp, trajectory.poses().back().timestamp);
      });
}

}  // namespace segslam::python
