#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace segslam::eval {

// One data series of a plot.
struct PlotSeries {
  std::string label{};  // legend text
  std::vector<double> x{};
  std::vector<double> y{};         // same length as x; non-finite points are left out
  std::string colour = "#1f77b4";  // any SVG colour
  bool markers = false;            // dots instead of a line, for data without an order
  std::string dash{};              // SVG stroke-dasharray, e.g. "6,4"; empty = solid
};

// One panel: axes with ticks, grid, labels, title and a legend beside it.
struct Plot {
  std::string title{};
  std::string x_label{};
  std::string y_label{};
  std::vector<PlotSeries> series{};
  bool equal_aspect = false;  // one metre is as long on both axes (top views)
};

// Size of one panel in SVG pixels, including its margins.
struct PanelSize {
  double width = 860.0;
  double height = 360.0;
};

// A standalone SVG document with the plots stacked top to bottom.
std::string renderSvg(std::span<const Plot> plots, const PanelSize& size = {});

// Writes renderSvg() to a file; throws util::Error naming the file when it cannot be written.
void writeSvg(const std::filesystem::path& file, std::span<const Plot> plots,
              const PanelSize& size = {});

}  // namespace segslam::eval
