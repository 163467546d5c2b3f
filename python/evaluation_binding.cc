#include <fmt/format.h>
#include <pybind11/numpy.h>

#include "module_parts.h"
#include "segslam/eval/ate.h"
#include "segslam/eval/rpe.h"

namespace segslam::python {

namespace {

py::array_t<double> ateErrors(const eval::AteResult& result) {
  py::array_t<double> errors(static_cast<py::ssize_t>(result.pairs.size()));
  auto values = errors.mutable_unchecked<1>();
  for (std::size_t i = 0; i < result.pairs.size(); ++i) {
    values(static_cast<py::ssize_t>(i)) = result.pairs[i].error;
  }
  return errors;
}

py::array_t<double> alignmentMatrix(const eval::AteResult& result) {
  const Eigen::Matrix4d matrix = result.alignment.matrix();
  py::array_t<double> array({4, 4});
  auto values = array.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) values(r, c) = matrix(r, c);
  }
  return array;
}

eval::AteResult ate(const core::Trajectory& ground_truth, const core::Trajectory& estimate,
                    double max_difference, double offset, double scale,
                    const std::string& alignment) {
  const auto method = eval::parseAlignmentMethod(alignment);
  if (!method) {
    throw py::value_error(
        fmt::format("unknown alignment '{}' (known: se3, sim3, none)", alignment));
  }
  const py::gil_scoped_release unlocked;
  return eval::evaluateAte(ground_truth, estimate, {max_difference, offset, scale, *method});
}

eval::RpeResult rpe(const core::Trajectory& ground_truth, const core::Trajectory& estimate,
                    double delta, const std::string& delta_unit, bool fixed_delta,
                    std::size_t max_pairs, double offset, double scale, std::uint64_t seed) {
  const auto unit = eval::parseDeltaUnit(delta_unit);
  if (!unit) {
    throw py::value_error(
        fmt::format("unknown delta_unit '{}' (known: s, f, m, deg, rad)", delta_unit));
  }
  eval::RpeOptions options;
  options.fixed_delta = fixed_delta;
  options.delta = delta;
  options.delta_unit = *unit;
  options.max_pairs = max_pairs;
  options.offset = offset;
  options.scale = scale;
  options.seed = seed;
  const py::gil_scoped_release unlocked;
  return eval::evaluateRpe(ground_truth, estimate, options);
}

std::string describeStatistics(const eval::ErrorStatistics& s) {
  return fmt::format(
      "ErrorStatistics(count={}, rmse={:.6g}, mean={:.6g}, median={:.6g}, "
      "std={:.6g}, min={:.6g}, max={:.6g})",
      s.count, s.rmse, s.mean, s.median, s.std, s.min, s.max);
}

}  // namespace

void bindEvaluation(py::module_& module) {
  py::class_<eval::ErrorStatistics>(module, "ErrorStatistics",
                                    "Statistics of a list of errors, as the TUM tools print them.")
      .def_readonly("count", &eval::ErrorStatistics::count)
      .def_readonly("rmse", &eval::ErrorStatistics::rmse)
      .def_readonly("mean", &eval::ErrorStatistics::mean)
      .def_readonly("median", &eval::ErrorStatistics::median)
      .def_readonly("std", &eval::ErrorStatistics::std)
      .def_readonly("min", &eval::ErrorStatistics::min)
      .def_readonly("max", &eval::ErrorStatistics::max)
      .def("__repr__", &describeStatistics);
  py::class_<eval::AteResult>(module, "AteResult", "Absolute trajectory error.")
      .def_readonly("statistics", &eval::AteResult::statistics, "Metres.")
      .def_property_readonly("rmse", [](const eval::AteResult& r) { return r.statistics.rmse; })
      .def_property_readonly("errors", &ateErrors, "float64 (M,): metres per matched pose.")
      .def_property_readonly("alignment", &alignmentMatrix,
                             "float64 (4, 4): maps the (scaled) estimate onto the ground truth.")
      .def_readonly("aligned_estimate", &eval::AteResult::aligned_estimate);
  py::class_<eval::RpeResult>(module, "RpeResult", "Relative pose error.")
      .def_readonly("translational", &eval::RpeResult::translational, "Metres.")
      .def_readonly("rotational_deg", &eval::RpeResult::rotational_deg, "Degrees.")
      .def_property_readonly("pairs", [](const eval::RpeResult& r) { return r.pairs.size(); });
  module.def("ate", &ate, py::arg("ground_truth"), py::arg("estimate"), py::kw_only(),
             py::arg("max_difference") = 0.02, py::arg("offset") = 0.0, py::arg("scale") = 1.0,
             py::arg("alignment") = "se3",
             "Absolute trajectory error as TUM evaluate_ate.py and `segslam eval` compute it. "
             "ValueError when fewer than 2 poses match.");
  module.def("rpe", &rpe, py::arg("ground_truth"), py::arg("estimate"), py::kw_only(),
             py::arg("delta") = 1.0, py::arg("delta_unit") = "s", py::arg("fixed_delta") = true,
             py::arg("max_pairs") = 10000, py::arg("offset") = 0.0, py::arg("scale") = 1.0,
             py::arg("seed") = 0,
             "Relative pose error as TUM evaluate_rpe.py and `segslam eval` compute it "
             "(delta_unit s, f, m, deg or rad). ValueError when too few pairs remain.");
}

}  // namespace segslam::python
