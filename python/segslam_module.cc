#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "module_parts.h"
#include "segslam/util/error.h"
#include "segslam/util/logging.h"

namespace py = pybind11;

namespace {

void setLogLevel(const std::string& level) {
  const auto names = segslam::util::logLevelNames();
  if (std::find(names.begin(), names.end(), level) == names.end()) {
    throw py::value_error(
        fmt::format("unknown log level '{}' (known: {})", level, fmt::join(names, ", ")));
  }
  segslam::util::setupLogging(level);
}

}  // namespace

PYBIND11_MODULE(segslam, module) {
  module.doc() =
      "segslam: RGB-D SLAM in dynamic scenes. Numpy frames in; poses, dynamic masks, trajectories, "
      "evaluations and dense maps out. See docs/python.md.";
  module.attr("__version__") = SEGSLAM_VERSION;
  // util::Error is what the user can cause (a malformed file, an unknown name, a missing
  // network): Python callers see it as bad input.
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const segslam::util::Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  // A library is quiet unless asked: the CLI's progress messages would clutter notebooks.
  segslam::util::setupLogging("warn");
  module.def("set_log_level", &setLogLevel, py::arg("level"),
             "Log level of segslam's messages on stderr: trace, debug, info, warn (the default), "
             "error or off.");
  segslam::python::bindCamera(module);
  segslam::python::bindTrajectory(module);
  segslam::python::bindDataset(module);
  segslam::python::bindSegmenter(module);
  segslam::python::bindDenseMap(module);
  segslam::python::bindOccupancy(module);
  segslam::python::bindSystem(module);
  segslam::python::bindEvaluation(module);
}
