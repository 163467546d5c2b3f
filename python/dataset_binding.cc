#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <opencv2/imgproc.hpp>

#include "module_parts.h"
#include "numpy_arrays.h"
#include "segslam/io/tum_dataset.h"

namespace segslam::python {

namespace {

// One frame of a dataset as numpy arrays.
struct Frame {
  double timestamp = 0.0;
  py::array rgb;
  py::array depth;
  py::object mask = py::none();
};

io::TumDataset openDataset(const std::filesystem::path& path,
                           const std::optional<std::filesystem::path>& camera_file,
                           const std::optional<std::string>& camera_preset,
                           double max_time_difference,
                           const std::optional<std::string>& ground_truth_frame) {
  io::DatasetOptions options;
  options.camera_file = camera_file;
  options.camera_preset = camera_preset;
  options.max_time_difference = max_time_difference;
  if (ground_truth_frame)
    options.ground_truth_frame = io::requireGroundTruthFrame(*ground_truth_frame);
  const py::gil_scoped_release unlocked;
  return io::TumDataset::open(path, options);
}

Frame frameAt(const io::TumDataset& dataset, py::ssize_t index) {
  const auto size = static_cast<py::ssize_t>(dataset.size());
  if (index < 0) index += size;
  if (index < 0 || index >= size) {
    throw py::index_error(fmt::format("frame {} of a dataset of {} frames", index, size));
  }
  io::RgbdFrame loaded;
  {
    const py::gil_scoped_release unlocked;
    loaded = dataset.loadFrame(static_cast<std::size_t>(index), {dataset.hasMasks(), false, false});
    cv::cvtColor(loaded.rgb, loaded.rgb, cv::COLOR_BGR2RGB);
  }
  Frame frame{loaded.timestamp, toNumpy(loaded.rgb), toNumpy(loaded.depth)};
  if (!loaded.mask.empty()) frame.mask = toNumpy(loaded.mask);
  return frame;
}

py::array_t<double> frameTimestamps(const io::TumDataset& dataset) {
  py::array_t<double> stamps(static_cast<py::ssize_t>(dataset.size()));
  auto values = stamps.mutable_unchecked<1>();
  for (std::size_t i = 0; i < dataset.size(); ++i) {
    values(static_cast<py::ssize_t>(i)) = dataset.frames()[i].timestamp;
  }
  return stamps;
}

}  // namespace

void bindDataset(py::module_& module) {
  py::class_<Frame>(module, "Frame", "One RGB-D frame of a dataset.")
      .def_readonly("timestamp", &Frame::timestamp, "Seconds (the colour image's).")
      .def_readonly("rgb", &Frame::rgb, "uint8 (H, W, 3), RGB.")
      .def_readonly("depth", &Frame::depth, "float32 (H, W), metres, 0 = no measurement.")
      .def_readonly("mask", &Frame::mask,
                    "uint8 (H, W) ground-truth dynamic mask (255 = dynamic), or None when the "
                    "dataset has no mask.txt.")
      .def("__repr__", [](const Frame& frame) {
        return fmt::format("Frame(timestamp={:.6f})", frame.timestamp);
      });

  py::class_<io::TumDataset>(
      module, "TumDataset",
      "A sequence in the TUM RGB-D layout (rgb.txt, depth.txt, optional groundtruth.txt and "
      "mask.txt), as `segslam run --dataset` reads it. Indexing and iteration load frames.")
      .def(py::init(&openDataset), py::arg("path"), py::arg("camera_file") = py::none(),
           py::arg("camera_preset") = py::none(), py::arg("max_time_difference") = 0.02,
           py::arg("ground_truth_frame") = py::none(),
           "Opens and checks the dataset. The camera: camera_file, else camera_preset, else the "
           "folder's camera.yaml or calibration.txt, else the preset its name gives (TUM, "
           "Bonn). ground_truth_frame: what groundtruth.txt holds poses of, 'camera' or "
           "'bonn-markers'; None: as the folder's name tells (a Bonn sequence's markers). "
           "Listed images the folder lacks leave their frames out (absent_images). ValueError "
           "naming the file and line when something is wrong.")
      .def("__len__", &io::TumDataset::size)
      .def("__getitem__", &frameAt, py::arg("index"),
           "The frame at `index` (negative counts from the end); IndexError beyond.")
      .def_property_readonly("camera", &io::TumDataset::camera)
      .def_property_readonly("camera_source", &io::TumDataset::cameraSource,
                             "Where the camera settings came from.")
      .def_property_readonly("folder", &io::TumDataset::folder)
      .def_property_readonly("timestamps", &frameTimestamps, "float64 (N,), the frames'.")
      .def_property_readonly("ground_truth", &io::TumDataset::groundTruth,
                             "The camera's poses from groundtruth.txt (converted where it holds "
                             "others, see ground_truth_frame), or None.")
      .def_property_readonly(
          "ground_truth_frame",
          [](const io::TumDataset& dataset) {
            return io::groundTruthFrameName(dataset.groundTruthFrame());
          },
          "What groundtruth.txt holds poses of: 'camera' or 'bonn-markers'.")
      .def_property_readonly(
          "absent_images",
          [](const io::TumDataset& dataset) {
            std::vector<std::filesystem::path> paths;
            for (const auto& image : dataset.absentImages()) paths.push_back(image.path);
            return paths;
          },
          "Images the lists name that the folder lacks; their frames are left out.")
      .def_property_readonly("has_masks", &io::TumDataset::hasMasks);
}

}  // namespace segslam::python
