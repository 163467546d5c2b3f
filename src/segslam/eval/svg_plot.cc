#include "segslam/eval/svg_plot.h"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string_view>
#include <system_error>

#include "segslam/eval/nice_ticks.h"
#include "segslam/util/error.h"

namespace segslam::eval {

namespace {

// Room around the plot area for the title, tick labels, axis labels and the legend.
constexpr double kMarginLeft = 80.0;
constexpr double kMarginRight = 250.0;
constexpr double kMarginTop = 36.0;
constexpr double kMarginBottom = 52.0;
// Pixels per tick, roughly: enough room for a label.
constexpr double kPixelsPerXTick = 110.0;
constexpr double kPixelsPerYTick = 55.0;

struct Bounds {
  double x_low = std::numeric_limits<double>::infinity();
  double x_high = -std::numeric_limits<double>::infinity();
  double y_low = std::numeric_limits<double>::infinity();
  double y_high = -std::numeric_limits<double>::infinity();

  void include(double x, double y) {
    x_low = std::min(x_low, x);
    x_high = std::max(x_high, x);
    y_low = std::min(y_low, y);
    y_high = std::max(y_high, y);
  }
  [[nodiscard]] bool empty() const { return !(x_low <= x_high); }
};

bool isFinitePoint(const PlotSeries& series, std::size_t k) {
  return std::isfinite(series.x[k]) && std::isfinite(series.y[k]);
}

std::size_t pointCount(const PlotSeries& series) {
  return std::min(series.x.size(), series.y.size());
}

Bounds dataBounds(const Plot& plot) {
  Bounds bounds;
  for (const auto& series : plot.series) {
    for (std::size_t k = 0; k < pointCount(series); ++k) {
      if (isFinitePoint(series, k)) bounds.include(series.x[k], series.y[k]);
    }
  }
  if (bounds.empty()) bounds = {0.0, 1.0, 0.0, 1.0};
  return bounds;
}

// The plot area in pixels and the data ranges it shows.
struct Frame {
  double left = 0.0;
  double top = 0.0;
  double width = 0.0;
  double height = 0.0;
  AxisRange x;
  AxisRange y;

  [[nodiscard]] double toX(double value) const {
    return left + (value - x.low) / (x.high - x.low) * width;
  }
  [[nodiscard]] double toY(double value) const {
    return top + height - (value - y.low) / (y.high - y.low) * height;
  }
};

// Widens the shorter range around its centre until a data unit spans as many pixels on both axes.
void equaliseScales(Bounds& bounds, double width, double height) {
  const double x_span = std::max(bounds.x_high - bounds.x_low, 1e-9);
  const double y_span = std::max(bounds.y_high - bounds.y_low, 1e-9);
  const double units_per_pixel = std::max(x_span / width, y_span / height);
  const double x_centre = (bounds.x_low + bounds.x_high) / 2.0;
  const double y_centre = (bounds.y_low + bounds.y_high) / 2.0;
  bounds.x_low = x_centre - units_per_pixel * width / 2.0;
  bounds.x_high = x_centre + units_per_pixel * width / 2.0;
  bounds.y_low = y_centre - units_per_pixel * height / 2.0;
  bounds.y_high = y_centre + units_per_pixel * height / 2.0;
}

Frame layoutFrame(const Plot& plot, const PanelSize& size, double panel_top) {
  Frame frame;
  frame.left = kMarginLeft;
  frame.top = panel_top + kMarginTop;
  frame.width = size.width - kMarginLeft - kMarginRight;
  frame.height = size.height - kMarginTop - kMarginBottom;
  const int x_ticks = std::max(2, static_cast<int>(frame.width / kPixelsPerXTick));
  const int y_ticks = std::max(2, static_cast<int>(frame.height / kPixelsPerYTick));
  Bounds bounds = dataBounds(plot);
  if (!plot.equal_aspect) {
    frame.x = niceAxis(bounds.x_low, bounds.x_high, x_ticks);
    frame.y = niceAxis(bounds.y_low, bounds.y_high, y_ticks);
    return frame;
  }
  // Equal scales fix the ranges, so they are not rounded outwards to whole ticks; a small margin
  // keeps the outermost points off the frame.
  const double pad = 0.04 * std::max(bounds.x_high - bounds.x_low, bounds.y_high - bounds.y_low);
  bounds = {bounds.x_low - pad, bounds.x_high + pad, bounds.y_low - pad, bounds.y_high + pad};
  equaliseScales(bounds, frame.width, frame.height);
  // One step for both axes, so that the grid is made of squares.
  const double step = std::min(niceStep(bounds.x_high - bounds.x_low, x_ticks),
                               niceStep(bounds.y_high - bounds.y_low, y_ticks));
  frame.x = {bounds.x_low, bounds.x_high, step};
  frame.y = {bounds.y_low, bounds.y_high, step};
  return frame;
}

std::string escapeXml(std::string_view text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

using Output = std::back_insert_iterator<std::string>;

void renderAxes(Output out, const Frame& frame) {
  for (const double tick : tickValues(frame.x.low, frame.x.high, frame.x.step)) {
    const double px = frame.toX(tick);
    fmt::format_to(out,
                   R"(<line x1="{0:.2f}" y1="{1:.2f}" x2="{0:.2f}" y2="{2:.2f}" stroke="#e0e0e0"/>)"
                   "\n",
                   px, frame.top, frame.top + frame.height);
    fmt::format_to(out,
                   R"(<text x="{:.2f}" y="{:.2f}" text-anchor="middle">{}</text>)"
                   "\n",
                   px, frame.top + frame.height + 16.0, formatTick(tick, frame.x.step));
  }
  for (const double tick : tickValues(frame.y.low, frame.y.high, frame.y.step)) {
    const double py = frame.toY(tick);
    fmt::format_to(out,
                   R"(<line x1="{0:.2f}" y1="{1:.2f}" x2="{2:.2f}" y2="{1:.2f}" stroke="#e0e0e0"/>)"
                   "\n",
                   frame.left, py, frame.left + frame.width);
    fmt::format_to(out,
                   R"(<text x="{:.2f}" y="{:.2f}" text-anchor="end">{}</text>)"
                   "\n",
                   frame.left - 6.0, py + 4.0, formatTick(tick, frame.y.step));
  }
  fmt::format_to(out,
                 R"(<rect x="{:.2f}" y="{:.2f}" width="{:.2f}" height="{:.2f}" fill="none" )"
                 R"(stroke="#333333"/>)"
                 "\n",
                 frame.left, frame.top, frame.width, frame.height);
}

void renderLabels(Output out, const Plot& plot, const Frame& frame) {
  const double centre_x = frame.left + frame.width / 2.0;
  const double centre_y = frame.top + frame.height / 2.0;
  fmt::format_to(out,
                 R"(<text x="{:.2f}" y="{:.2f}" text-anchor="middle" font-size="15" )"
                 R"(font-weight="bold">{}</text>)"
                 "\n",
                 centre_x, frame.top - 12.0, escapeXml(plot.title));
  fmt::format_to(out,
                 R"(<text x="{:.2f}" y="{:.2f}" text-anchor="middle">{}</text>)"
                 "\n",
                 centre_x, frame.top + frame.height + 38.0, escapeXml(plot.x_label));
  fmt::format_to(out,
                 R"svg(<text transform="translate({:.2f},{:.2f}) rotate(-90)" )svg"
                 R"(text-anchor="middle">{}</text>)"
                 "\n",
                 frame.left - 58.0, centre_y, escapeXml(plot.y_label));
}

std::string strokeStyle(const PlotSeries& series) {
  return fmt::format(R"(fill="none" stroke="{}" stroke-width="1.5"{})", escapeXml(series.colour),
                     series.dash.empty()
                         ? std::string()
                         : fmt::format(R"( stroke-dasharray="{}")", escapeXml(series.dash)));
}

void renderLine(Output out, const Frame& frame, const PlotSeries& series) {
  // A non-finite point ends one polyline and the next finite point starts another.
  std::string points;
  const auto flush = [&] {
    if (!points.empty()) {
      fmt::format_to(out,
                     R"(<polyline points="{}" {}/>)"
                     "\n",
                     points, strokeStyle(series));
    }
    points.clear();
  };
  for (std::size_t k = 0; k < pointCount(series); ++k) {
    if (!isFinitePoint(series, k)) {
      flush();
      continue;
    }
    if (!points.empty()) points += ' ';
    fmt::format_to(std::back_inserter(points), "{:.2f},{:.2f}", frame.toX(series.x[k]),
                   frame.toY(series.y[k]));
  }
  flush();
}

void renderMarkers(Output out, const Frame& frame, const PlotSeries& series) {
  fmt::format_to(out,
                 R"(<g fill="{}">)"
                 "\n",
                 escapeXml(series.colour));
  for (std::size_t k = 0; k < pointCount(series); ++k) {
    if (!isFinitePoint(series, k)) continue;
    fmt::format_to(out,
                   R"(<circle cx="{:.2f}" cy="{:.2f}" r="1.8"/>)"
                   "\n",
                   frame.toX(series.x[k]), frame.toY(series.y[k]));
  }
  fmt::format_to(out, "</g>\n");
}

void renderLegend(Output out, const Plot& plot, const Frame& frame) {
  const double x = frame.left + frame.width + 14.0;
  double y = frame.top + 12.0;
  for (const auto& series : plot.series) {
    if (series.markers) {
      fmt::format_to(out,
                     R"(<circle cx="{:.2f}" cy="{:.2f}" r="3" fill="{}"/>)"
                     "\n",
                     x + 12.0, y, escapeXml(series.colour));
    } else {
      fmt::format_to(out,
                     R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" {}/>)"
                     "\n",
                     x, y, x + 24.0, y, strokeStyle(series));
    }
    fmt::format_to(out,
                   R"(<text x="{:.2f}" y="{:.2f}">{}</text>)"
                   "\n",
                   x + 30.0, y + 4.0, escapeXml(series.label));
    y += 20.0;
  }
}

void renderPanel(Output out, const Plot& plot, const PanelSize& size, std::size_t index) {
  const Frame frame = layoutFrame(plot, size, static_cast<double>(index) * size.height);
  renderAxes(out, frame);
  renderLabels(out, plot, frame);
  // Clipping keeps lines that leave the axis range (e.g. after a bad alignment) inside the frame.
  fmt::format_to(out,
                 R"(<clipPath id="plot{0}"><rect x="{1:.2f}" y="{2:.2f}" width="{3:.2f}" )"
                 R"(height="{4:.2f}"/></clipPath>)"
                 "\n"
                 R"svg(<g clip-path="url(#plot{0})">)svg"
                 "\n",
                 index, frame.left, frame.top, frame.width, frame.height);
  for (const auto& series : plot.series) {
    if (series.markers) {
      renderMarkers(out, frame, series);
    } else {
      renderLine(out, frame, series);
    }
  }
  fmt::format_to(out, "</g>\n");
  renderLegend(out, plot, frame);
}

}  // namespace

std::string renderSvg(std::span<const Plot> plots, const PanelSize& size) {
  const double height = size.height * static_cast<double>(std::max<std::size_t>(plots.size(), 1));
  std::string svg;
  auto out = std::back_inserter(svg);
  fmt::format_to(out,
                 R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0:.0f}" height="{1:.0f}" )"
                 R"(viewBox="0 0 {0:.0f} {1:.0f}" font-family="sans-serif" font-size="12">)"
                 "\n"
                 R"(<rect width="100%" height="100%" fill="white"/>)"
                 "\n",
                 size.width, height);
  for (std::size_t k = 0; k < plots.size(); ++k) renderPanel(out, plots[k], size, k);
  svg += "</svg>\n";
  return svg;
}

void writeSvg(const std::filesystem::path& file, std::span<const Plot> plots,
              const PanelSize& size) {
  try {
    auto out = fmt::output_file(file.string());
    out.print("{}", renderSvg(plots, size));
  } catch (const std::system_error& e) {
    util::failAt(file, fmt::format("cannot write: {}", e.what()));
  }
}

}  // namespace segslam::eval
