#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <mutex>
#include <opencv2/imgproc.hpp>

#include "default_settings.h"
#include "module_parts.h"
#include "numpy_arrays.h"
#include "segslam/segmentation/semantic_segmenter.h"

namespace segslam::python {

namespace {

// A semantic segmentation network on its own. The network keeps state between passes, so calls
// from several threads take turns.
class Segmenter {
 public:
  Segmenter(const std::filesystem::path& config_file,
            const std::optional<std::filesystem::path>& model_file)
      : config_(segmentation::readModelConfig(config_file)),
        segmenter_(config_, segmentation::resolveModelFile(config_, config_file, model_file)) {}

  std::pair<py::array, py::array> segment(const py::array& rgb) {
    requireDtype(rgb, py::dtype::of<std::uint8_t>(), "rgb");
    if (rgb.ndim() != 3 || rgb.shape(2) != 3 || rgb.shape(0) == 0 || rgb.shape(1) == 0) {
      throw py::value_error(
          fmt::format("rgb must have shape (height, width, 3), not {}", shapeText(rgb)));
    }
    const py::array pixels = contiguous(rgb);
    const cv::Mat view = matView(pixels, CV_8UC3);
    segmentation::SemanticMasks masks;
    {
      const py::gil_scoped_release unlocked;
      cv::Mat bgr;
      cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
      const std::lock_guard lock(mutex_);
      masks = segmenter_.segment(bgr);
    }
    return {toNumpy(masks.dynamic), toNumpy(masks.labels)};
  }

  [[nodiscard]] const segmentation::ModelConfig& config() const { return config_; }

 private:
  segmentation::ModelConfig config_;
  std::mutex mutex_;
  segmentation::SemanticSegmenter segmenter_;
};

std::unique_ptr<Segmenter> makeSegmenter(const std::filesystem::path& config_file,
                                         const std::optional<std::filesystem::path>& model_file) {
  const py::gil_scoped_release unlocked;
  return std::make_unique<Segmenter>(config_file, model_file);
}

}  // namespace

void bindSegmenter(py::module_& module) {
  py::class_<Segmenter>(module, "Segmenter",
                        "A semantic segmentation network (ONNX, run by OpenCV) as a model config "
                        "(config/models/*.yaml) describes it.")
      .def(py::init(&makeSegmenter), py::arg("model_config") = defaultSegmentationConfig(),
           py::arg("model") = py::none(),
           "Loads the network: `model` overrides the config's file, else the config's path or "
           "$SEGSLAM_MODEL_DIR. ValueError listing the places tried when it is not found.")
      .def("segment", &Segmenter::segment, py::arg("rgb"),
           "Segments an RGB image (uint8 (H, W, 3), any size). Returns (mask, labels): uint8 "
           "(H, W) each, mask 255 where a dynamic class is, labels the index into `classes`.")
      .def_property_readonly("name", [](const Segmenter& s) { return s.config().name; })
      .def_property_readonly("classes", [](const Segmenter& s) { return s.config().classes; })
      .def_property_readonly("dynamic_classes",
                             [](const Segmenter& s) { return s.config().dynamic_classes; });
}

}  // namespace segslam::python
