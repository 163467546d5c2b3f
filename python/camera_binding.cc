#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "module_parts.h"
#include "numpy_arrays.h"
#include "segslam/io/camera_config.h"

namespace segslam::python {

namespace {

core::Camera makeCamera(int width, int height, double fx, double fy, double cx, double cy,
                        const std::array<double, 5>& distortion, double depth_factor, double fps,
                        const std::string& name, double rolling_shutter_readout) {
  const core::Camera camera{
      name, width, height, fx, fy, cx, cy, distortion, depth_factor, fps, rolling_shutter_readout};
  io::validateCamera(camera, "Camera");
  return camera;
}

py::array_t<double> intrinsicMatrix(const core::Camera& camera) {
  py::array_t<double> matrix({3, 3});
  auto k = matrix.mutable_unchecked<2>();
  for (py::ssize_t r = 0; r < 3; ++r) {
    for (py::ssize_t c = 0; c < 3; ++c) k(r, c) = 0.0;
  }
  k(0, 0) = camera.fx;
  k(1, 1) = camera.fy;
  k(0, 2) = camera.cx;
  k(1, 2) = camera.cy;
  k(2, 2) = 1.0;
  return matrix;
}

std::string describe(const core::Camera& camera) {
  return fmt::format(
      "Camera(name='{}', width={}, height={}, fx={}, fy={}, cx={}, cy={}, depth_factor={}, "
      "fps={}, rolling_shutter_readout={})",
      camera.name, camera.width, camera.height, camera.fx, camera.fy, camera.cx, camera.cy,
      camera.depth_factor, camera.fps, camera.rolling_shutter_readout_s);
}

}  // namespace

void bindCamera(py::module_& module) {
  const core::Camera defaults;
  py::class_<core::Camera>(module, "Camera",
                           "A pinhole RGB-D camera: intrinsics, Brown-Conrady distortion (k1 k2 p1 "
                           "p2 k3), depth factor (raw depth units per metre) and frame rate.")
      .def(py::init(&makeCamera), py::arg("width"), py::arg("height"), py::arg("fx"), py::arg("fy"),
           py::arg("cx"), py::arg("cy"), py::arg("distortion") = defaults.distortion,
           py::arg("depth_factor") = defaults.depth_factor, py::arg("fps") = defaults.fps,
           py::arg("name") = defaults.name,
           py::arg("rolling_shutter_readout") = defaults.rolling_shutter_readout_s,
           "A camera from its intrinsics. ValueError when a value is impossible.")
      .def_static("preset", &io::requireCameraPreset, py::arg("name"),
                  "A preset: 'freiburg1', 'freiburg2', 'freiburg3' (TUM RGB-D) or 'bonn'.")
      .def_static("presets", &io::cameraPresetNames, "The preset names.")
      .def_static("from_yaml", &io::readCameraYaml, py::arg("path"),
                  "Reads camera settings YAML (the format of `segslam run --camera`).")
      .def(
          "to_yaml",
          [](const core::Camera& camera, const std::filesystem::path& path) {
            io::writeCameraYaml(path, camera);
          },
          py::arg("path"), "Writes the camera as settings YAML.")
      .def_readonly("name", &core::Camera::name)
      .def_readonly("width", &core::Camera::width)
      .def_readonly("height", &core::Camera::height)
      .def_readonly("fx", &core::Camera::fx)
      .def_readonly("fy", &core::Camera::fy)
      .def_readonly("cx", &core::Camera::cx)
      .def_readonly("cy", &core::Camera::cy)
      .def_readonly("distortion", &core::Camera::distortion, "(k1, k2, p1, p2, k3)")
      .def_readonly("depth_factor", &core::Camera::depth_factor, "Raw depth units per metre.")
      .def_readonly("fps", &core::Camera::fps)
      .def_readonly("rolling_shutter_readout", &core::Camera::rolling_shutter_readout_s,
                    "Seconds from the first row's exposure to the last's; 0: global shutter.")
      .def_property_readonly("intrinsics", &intrinsicMatrix, "The 3x3 matrix K (float64).")
      .def("__repr__", &describe);
}

}  // namespace segslam::python
