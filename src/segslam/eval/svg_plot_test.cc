#include "segslam/eval/svg_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>

#include "segslam/util/error.h"

namespace segslam::eval {
namespace {

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

// The pixel coordinates of the first polyline in an SVG document.
std::vector<std::pair<double, double>> firstPolyline(const std::string& svg) {
  const std::regex points_attribute(R"re(<polyline points="([^"]*)")re");
  std::smatch match;
  EXPECT_TRUE(std::regex_search(svg, match, points_attribute));
  std::vector<std::pair<double, double>> points;
  std::istringstream stream(match[1].str());
  double x = 0.0;
  double y = 0.0;
  char comma = 0;
  while (stream >> x >> comma >> y) points.emplace_back(x, y);
  return points;
}

Plot squarePlot(bool equal_aspect) {
  Plot plot{
      .title = "Square", .x_label = "x [m]", .y_label = "y [m]", .equal_aspect = equal_aspect};
  plot.series.push_back({"path", {0, 4, 4, 0, 0}, {0, 0, 1, 1, 0}});
  return plot;
}

TEST(SvgPlot, DocumentHasAxesLabelsLegendAndLines) {
  Plot plot{.title = "Errors <ATE & RPE>", .x_label = "time [s]", .y_label = "error [m]"};
  plot.series.push_back({"ATE", {0, 1, 2}, {0.1, 0.3, 0.2}, "#d62728"});
  plot.series.push_back({"RMSE", {0, 2}, {0.2, 0.2}, "#ff7f0e", false, "6,4"});
  const std::vector<Plot> plots{plot};
  const auto svg = renderSvg(plots);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(occurrences(svg, "<polyline"), 2u);
  EXPECT_NE(svg.find("Errors &lt;ATE &amp; RPE&gt;"), std::string::npos);
  EXPECT_NE(svg.find(">time [s]</text>"), std::string::npos);
  EXPECT_NE(svg.find(">error [m]</text>"), std::string::npos);
  EXPECT_NE(svg.find(">RMSE</text>"), std::string::npos);
  EXPECT_NE(svg.find(R"(stroke-dasharray="6,4")"), std::string::npos);
  // Nice ticks on the y axis: 0.10 ... 0.30 in steps of 0.05.
  EXPECT_NE(svg.find(">0.15</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.30</text>"), std::string::npos);
}

TEST(SvgPlot, EqualAspectDrawsAMetreEquallyLongOnBothAxes) {
  const std::vector<Plot> equal{squarePlot(true)};
  const auto points = firstPolyline(renderSvg(equal));
  ASSERT_EQ(points.size(), 5u);
  const double four_metres = std::abs(points[1].first - points[0].first);
  const double one_metre = std::abs(points[2].second - points[1].second);
  EXPECT_NEAR(four_metres / one_metre, 4.0, 0.01);

  const std::vector<Plot> stretched{squarePlot(false)};
  const auto free_points = firstPolyline(renderSvg(stretched));
  EXPECT_GT(std::abs(free_points[2].second - free_points[1].second),
            std::abs(free_points[1].first - free_points[0].first) / 4.0 * 1.5);
}

TEST(SvgPlot, NonFinitePointsBreakTheLine) {
  Plot plot{.title = "gap"};
  plot.series.push_back({"s", {0, 1, 2, 3, 4}, {0, 1, NAN, 3, 4}});
  const std::vector<Plot> plots{plot};
  EXPECT_EQ(occurrences(renderSvg(plots), "<polyline"), 2u);
}

TEST(SvgPlot, MarkersAreDots) {
  Plot plot{.title = "dots"};
  plot.series.push_back({"s", {0, 1, 2}, {0, 1, 2}, "black", true});
  const std::vector<Plot> plots{plot};
  const auto svg = renderSvg(plots);
  EXPECT_EQ(occurrences(svg, "<polyline"), 0u);
  EXPECT_EQ(occurrences(svg, "<circle"), 4u);  // three points and the legend's sample
}

TEST(SvgPlot, PanelsStackVertically) {
  const std::vector<Plot> plots{squarePlot(false), squarePlot(false), squarePlot(false)};
  const auto svg = renderSvg(plots, {.width = 500, .height = 200});
  EXPECT_NE(svg.find("height=\"600\""), std::string::npos);
  EXPECT_EQ(occurrences(svg, "<clipPath"), 3u);
}

TEST(SvgPlot, UnwritableFileNamesIt) {
  const std::vector<Plot> plots{squarePlot(true)};
  try {
    writeSvg("/nonexistent-folder/plot.svg", plots);
    FAIL() << "expected an error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/plot.svg"), std::string::npos);
  }
}

}  // namespace
}  // namespace segslam::eval
