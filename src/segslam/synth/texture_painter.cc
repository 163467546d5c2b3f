#include "segslam/synth/texture_painter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace segslam::synth {

namespace {

using Rng = std::mt19937_64;

// A texture being painted: the image plus what is needed to place marks in metres.
struct Canvas {
  cv::Mat image;  // CV_8UC3
  double texel = kTexelSize;
  Rng rng;

  [[nodiscard]] double px(double metres) const { return metres / texel; }
  [[nodiscard]] double areaM2() const { return image.cols * image.rows * texel * texel; }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  int uniformInt(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  cv::Point2f randomPoint() {
    return {static_cast<float>(uniform(0.0, image.cols)),
            static_cast<float>(uniform(0.0, image.rows))};
  }
  // Log-uniform sizes: as many small marks per octave as large ones, so every scale has corners.
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  // How many marks of a given density fit; fractional counts are rounded at random.
  int countFor(double per_m2) {
    const double expected = per_m2 * areaM2();
    const int whole = static_cast<int>(expected);
    return whole + (chance(expected - whole) ? 1 : 0);
  }
};

// Hue in degrees, saturation and value in [0, 1], to an OpenCV BGR colour.
cv::Scalar hsv(double hue, double saturation, double value) {
  hue = std::fmod(std::fmod(hue, 360.0) + 360.0, 360.0);
  const double c = value * saturation;
  const double x = c * (1.0 - std::abs(std::fmod(hue / 60.0, 2.0) - 1.0));
  const double m = value - c;
  std::array<double, 3> rgb{};
  switch (static_cast<int>(hue / 60.0)) {
    case 0:
      rgb = {c, x, 0};
      break;
    case 1:
      rgb = {x, c, 0};
      break;
    case 2:
      rgb = {0, c, x};
      break;
    case 3:
      rgb = {0, x, c};
      break;
    case 4:
      rgb = {x, 0, c};
      break;
    default:
      rgb = {c, 0, x};
      break;
  }
  return {(rgb[2] + m) * 255.0, (rgb[1] + m) * 255.0, (rgb[0] + m) * 255.0};
}

cv::Scalar anyColour(Canvas& canvas) {
  return hsv(canvas.uniform(0, 360), canvas.uniform(0.2, 0.95), canvas.uniform(0.1, 0.95));
}

cv::Scalar greyish(Canvas& canvas, double lo, double hi) {
  return hsv(canvas.uniform(0, 360), canvas.uniform(0.0, 0.15), canvas.uniform(lo, hi));
}

// Smooth random field in [-1, 1], `cell_x` x `cell_y` texels per random value.
cv::Mat noiseField(Canvas& canvas, double cell_x, double cell_y) {
  const int cols = std::max(2, static_cast<int>(std::ceil(canvas.image.cols / cell_x)) + 1);
  const int rows = std::max(2, static_cast<int>(std::ceil(canvas.image.rows / cell_y)) + 1);
  cv::Mat coarse(rows, cols, CV_32F);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c)
      coarse.at<float>(r, c) = static_cast<float>(canvas.uniform(-1, 1));
  }
  cv::Mat fine;
  cv::resize(coarse, fine, canvas.image.size(), 0, 0, cv::INTER_CUBIC);
  return fine;
}

// Adds brightness noise at several scales (metres), amplitude in grey levels per octave.
void addNoise(Canvas& canvas, double amplitude, std::initializer_list<double> scales_m,
              double stretch_x = 1.0) {
  cv::Mat total = cv::Mat::zeros(canvas.image.size(), CV_32F);
  for (double scale : scales_m) {
    const double cell = std::max(1.0, canvas.px(scale));
    total += noiseField(canvas, cell * stretch_x, cell);
  }
  const auto gain = static_cast<float>(amplitude);
  for (int row = 0; row < canvas.image.rows; ++row) {
    const auto* noise = total.ptr<float>(row);
    auto* pixel = canvas.image.ptr<cv::Vec3b>(row);
    for (int col = 0; col < canvas.image.cols; ++col) {
      const float delta = noise[col] * gain;
      for (int c = 0; c < 3; ++c)
        pixel[col][c] = cv::saturate_cast<std::uint8_t>(pixel[col][c] + delta);
    }
  }
}

void fillPolygon(Canvas& canvas, const std::vector<cv::Point2f>& corners,
                 const cv::Scalar& colour) {
  std::vector<cv::Point> points;
  constexpr int kShift = 4;  // sub-texel precision for anti-aliased edges
  for (const auto& p : corners) {
    points.emplace_back(cvRound(p.x * (1 << kShift)), cvRound(p.y * (1 << kShift)));
  }
  cv::fillConvexPoly(canvas.image, points, colour, cv::LINE_AA, kShift);
}

std::vector<cv::Point2f> rotatedRect(cv::Point2f centre, float w, float h, float angle_deg) {
  cv::Point2f corners[4];
  cv::RotatedRect(centre, cv::Size2f(w, h), angle_deg).points(corners);
  return {corners, corners + 4};
}

void drawText(Canvas& canvas, cv::Point2f origin, double height_px, const cv::Scalar& colour,
              int length) {
  static constexpr std::string_view kGlyphs = "ABCDEFGHJKLMNPQRSTUVWXYZ0123456789#%&+=?";
  std::string text;
  for (int i = 0; i < length; ++i) {
    text += kGlyphs[canvas.uniformInt(0, static_cast<int>(kGlyphs.size()) - 1)];
  }
  const double scale = height_px / 22.0;
  const int thickness = std::max(1, static_cast<int>(height_px / 9.0));
  const int font = canvas.chance(0.5) ? cv::FONT_HERSHEY_SIMPLEX : cv::FONT_HERSHEY_DUPLEX;
  cv::putText(canvas.image, text, origin, font, scale, colour, thickness, cv::LINE_AA);
}

void drawChecker(Canvas& canvas, cv::Point2f centre, float size, const cv::Scalar& a,
                 const cv::Scalar& b) {
  const int cells = canvas.uniformInt(2, 5);
  const float cell = size / cells;
  const float angle = static_cast<float>(canvas.uniform(0, 90));
  const float c = std::cos(angle * static_cast<float>(CV_PI) / 180.0f);
  const float s = std::sin(angle * static_cast<float>(CV_PI) / 180.0f);
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const float ox = (i + 0.5f) * cell - size / 2;
      const float oy = (j + 0.5f) * cell - size / 2;
      const cv::Point2f at(centre.x + c * ox - s * oy, centre.y + s * ox + c * oy);
      fillPolygon(canvas, rotatedRect(at, cell, cell, angle), (i + j) % 2 ? a : b);
    }
  }
}

// Where and how a mark is drawn: centre and size in texels, orientation in degrees.
struct Mark {
  cv::Point2f centre;
  float size;
  float angle;
  cv::Scalar colour;
  int thickness;
};

void fillRotatedRect(Canvas& canvas, const Mark& mark) {
  const auto aspect = static_cast<float>(canvas.uniform(0.3, 1.0));
  fillPolygon(canvas, rotatedRect(mark.centre, mark.size, mark.size * aspect, mark.angle),
              mark.colour);
}

void outlineRotatedRect(Canvas& canvas, const Mark& mark) {
  const auto aspect = static_cast<float>(canvas.uniform(0.4, 1.0));
  const auto corners = rotatedRect(mark.centre, mark.size, mark.size * aspect, mark.angle);
  const std::vector<cv::Point> points(corners.begin(), corners.end());
  cv::polylines(canvas.image, points, true, mark.colour, mark.thickness, cv::LINE_AA);
}

void drawDisc(Canvas& canvas, const Mark& mark, bool filled) {
  const int radius = std::max(filled ? 1 : 2, static_cast<int>(mark.size / 2));
  cv::circle(canvas.image, mark.centre, radius, mark.colour, filled ? cv::FILLED : mark.thickness,
             cv::LINE_AA);
}

void drawStroke(Canvas& canvas, const Mark& mark) {
  const float radians = mark.angle * static_cast<float>(CV_PI) / 180.0f;
  const cv::Point2f half(mark.size / 2 * std::cos(radians), mark.size / 2 * std::sin(radians));
  cv::line(canvas.image, mark.centre - half, mark.centre + half, mark.colour, mark.thickness,
           cv::LINE_AA);
}

void fillTriangle(Canvas& canvas, const Mark& mark) {
  std::vector<cv::Point2f> corners;
  for (int k = 0; k < 3; ++k) {
    const double a = (mark.angle + 120.0 * k + canvas.uniform(-25.0, 25.0)) * CV_PI / 180.0;
    corners.emplace_back(mark.centre.x + mark.size / 2 * static_cast<float>(std::cos(a)),
                         mark.centre.y + mark.size / 2 * static_cast<float>(std::sin(a)));
  }
  fillPolygon(canvas, corners, mark.colour);
}

// One random sharp-edged mark of about `size` texels.
void drawShape(Canvas& canvas, cv::Point2f centre, double size, const cv::Scalar& colour) {
  const Mark mark{centre, static_cast<float>(size), static_cast<float>(canvas.uniform(0, 180)),
                  colour, std::max(2, static_cast<int>(size / 8.0))};
  switch (canvas.uniformInt(0, 7)) {
    case 0:
      fillRotatedRect(canvas, mark);
      break;
    case 1:
      outlineRotatedRect(canvas, mark);
      break;
    case 2:
      drawDisc(canvas, mark, true);
      break;
    case 3:
      drawDisc(canvas, mark, false);
      break;
    case 4:
      drawStroke(canvas, mark);
      break;
    case 5:
      fillTriangle(canvas, mark);
      break;
    case 6:
      drawChecker(canvas, centre, mark.size, colour, anyColour(canvas));
      break;
    default:
      drawText(canvas, centre, std::max(6.0, size / 2), colour, canvas.uniformInt(2, 6));
  }
}

template <typename ColourFn>
void scatterShapes(Canvas& canvas, double per_m2, double min_m, double max_m, ColourFn colour) {
  const int count = canvas.countFor(per_m2);
  for (int i = 0; i < count; ++i) {
    const double size = canvas.px(canvas.logUniform(min_m, max_m));
    drawShape(canvas, canvas.randomPoint(), size, colour());
  }
}

void scatterText(Canvas& canvas, double per_m2, double min_m, double max_m, const cv::Scalar& ink) {
  const int count = canvas.countFor(per_m2);
  for (int i = 0; i < count; ++i) {
    drawText(canvas, canvas.randomPoint(), canvas.px(canvas.uniform(min_m, max_m)), ink,
             canvas.uniformInt(3, 10));
  }
}

void paintPosters(Canvas& canvas) {
  const int count = canvas.countFor(0.35);
  for (int i = 0; i < count; ++i) {
    const double w = canvas.px(canvas.uniform(0.25, 0.8));
    const double h = canvas.px(canvas.uniform(0.25, 0.8));
    const cv::Point2f corner = canvas.randomPoint();
    const cv::Rect box(cv::Point(cvRound(corner.x), cvRound(corner.y)),
                       cv::Size(cvRound(w), cvRound(h)));
    const cv::Rect inside = box & cv::Rect(0, 0, canvas.image.cols, canvas.image.rows);
    if (inside.area() <= 0) continue;
    canvas.image(inside).setTo(anyColour(canvas));
    Canvas poster{canvas.image(inside), canvas.texel, Rng(canvas.rng())};
    scatterShapes(poster, 120.0, 0.01, 0.12, [&] { return anyColour(poster); });
    scatterText(poster, 30.0, 0.01, 0.04, greyish(poster, 0.0, 0.2));
    cv::rectangle(canvas.image, box, greyish(canvas, 0.05, 0.3),
                  std::max(2, static_cast<int>(canvas.px(0.012))), cv::LINE_AA);
  }
}

void paintWallpaper(Canvas& canvas) {
  canvas.image.setTo(
      hsv(canvas.uniform(0, 360), canvas.uniform(0.08, 0.3), canvas.uniform(0.7, 0.9)));
  addNoise(canvas, 7.0, {0.015, 0.06, 0.3});
  scatterShapes(canvas, 45.0, 0.015, 0.25, [&] { return anyColour(canvas); });
  paintPosters(canvas);
  scatterText(canvas, 4.0, 0.015, 0.05, greyish(canvas, 0.0, 0.3));
}

void paintFloorPlanks(Canvas& canvas) {
  const double plank_width = canvas.px(canvas.uniform(0.12, 0.2));
  const double base_hue = canvas.uniform(18, 38);
  const cv::Scalar seam = hsv(base_hue, 0.6, 0.15);
  for (double y = 0; y < canvas.image.rows; y += plank_width) {
    double x = -canvas.px(canvas.uniform(0.0, 1.2));
    while (x < canvas.image.cols) {
      const double length = canvas.px(canvas.uniform(0.6, 1.6));
      const cv::Scalar colour = hsv(base_hue + canvas.uniform(-8, 8), canvas.uniform(0.4, 0.7),
                                    canvas.uniform(0.35, 0.75));
      cv::rectangle(canvas.image, cv::Point(cvRound(x), cvRound(y)),
                    cv::Point(cvRound(x + length), cvRound(y + plank_width)), colour, cv::FILLED);
      cv::line(canvas.image, cv::Point(cvRound(x), cvRound(y)),
               cv::Point(cvRound(x), cvRound(y + plank_width)), seam, 2, cv::LINE_AA);
      x += length;
    }
    cv::line(canvas.image, cv::Point(0, cvRound(y)), cv::Point(canvas.image.cols, cvRound(y)), seam,
             2, cv::LINE_AA);
  }
  addNoise(canvas, 10.0, {0.01, 0.03}, 12.0);
  addNoise(canvas, 5.0, {0.2});
  scatterShapes(canvas, 45.0, 0.01, 0.1, [&] { return anyColour(canvas); });
}

void paintCeilingTiles(Canvas& canvas) {
  canvas.image.setTo(greyish(canvas, 0.78, 0.9));
  addNoise(canvas, 6.0, {0.008, 0.05});
  scatterShapes(canvas, 250.0, 0.004, 0.012, [&] { return greyish(canvas, 0.35, 0.65); });
  const double tile = canvas.px(0.6);
  const int grout = std::max(2, static_cast<int>(canvas.px(0.012)));
  for (double x = 0; x < canvas.image.cols; x += tile) {
    cv::line(canvas.image, cv::Point(cvRound(x), 0), cv::Point(cvRound(x), canvas.image.rows),
             greyish(canvas, 0.3, 0.45), grout, cv::LINE_AA);
  }
  for (double y = 0; y < canvas.image.rows; y += tile) {
    cv::line(canvas.image, cv::Point(0, cvRound(y)), cv::Point(canvas.image.cols, cvRound(y)),
             greyish(canvas, 0.3, 0.45), grout, cv::LINE_AA);
  }
  scatterShapes(canvas, 6.0, 0.03, 0.3, [&] { return anyColour(canvas); });
}

void paintWood(Canvas& canvas) {
  canvas.image.setTo(
      hsv(canvas.uniform(18, 40), canvas.uniform(0.35, 0.6), canvas.uniform(0.35, 0.75)));
  addNoise(canvas, 14.0, {0.004, 0.015}, 15.0);
  scatterShapes(canvas, 40.0, 0.01, 0.12, [&] { return anyColour(canvas); });
  scatterText(canvas, 3.0, 0.01, 0.03, greyish(canvas, 0.0, 0.25));
}

void paintLaminate(Canvas& canvas) {
  canvas.image.setTo(
      hsv(canvas.uniform(0, 360), canvas.uniform(0.0, 0.4), canvas.uniform(0.35, 0.9)));
  addNoise(canvas, 6.0, {0.01, 0.08});
  scatterShapes(canvas, 55.0, 0.012, 0.15, [&] { return anyColour(canvas); });
  scatterText(canvas, 6.0, 0.01, 0.035, greyish(canvas, 0.0, 0.3));
}

void paintCardboard(Canvas& canvas) {
  canvas.image.setTo(
      hsv(canvas.uniform(25, 38), canvas.uniform(0.4, 0.55), canvas.uniform(0.55, 0.75)));
  addNoise(canvas, 9.0, {0.005, 0.04});
  const int label_count = canvas.countFor(10.0);
  for (int i = 0; i < label_count; ++i) {
    const cv::Point2f centre = canvas.randomPoint();
    const auto w = static_cast<float>(canvas.px(canvas.uniform(0.05, 0.15)));
    const auto h = static_cast<float>(canvas.px(canvas.uniform(0.03, 0.08)));
    fillPolygon(canvas, rotatedRect(centre, w, h, 0), greyish(canvas, 0.85, 1.0));
    drawText(canvas, centre - cv::Point2f(w / 2.5f, 0), h / 3, greyish(canvas, 0.0, 0.2), 5);
  }
  scatterShapes(canvas, 40.0, 0.01, 0.1, [&] { return greyish(canvas, 0.0, 0.3); });
}

void paintBook(Canvas& canvas) {
  canvas.image.setTo(
      hsv(canvas.uniform(0, 360), canvas.uniform(0.4, 0.9), canvas.uniform(0.25, 0.85)));
  addNoise(canvas, 5.0, {0.01});
  scatterShapes(canvas, 500.0, 0.005, 0.03, [&] { return anyColour(canvas); });
  const double band = canvas.px(canvas.uniform(0.01, 0.025));
  const cv::Scalar band_colour = anyColour(canvas);
  for (double y : {canvas.image.rows * 0.12, canvas.image.rows * 0.85}) {
    cv::rectangle(canvas.image, cv::Point(0, cvRound(y)),
                  cv::Point(canvas.image.cols, cvRound(y + band)), band_colour, cv::FILLED);
  }
}

void paintScreen(Canvas& canvas) {
  canvas.image.setTo(greyish(canvas, 0.05, 0.15));
  addNoise(canvas, 3.0, {0.02});
  const int windows = canvas.countFor(60.0);
  for (int i = 0; i < windows; ++i) {
    const cv::Point2f centre = canvas.randomPoint();
    const auto w = static_cast<float>(canvas.px(canvas.uniform(0.06, 0.25)));
    const auto h = static_cast<float>(canvas.px(canvas.uniform(0.05, 0.18)));
    fillPolygon(canvas, rotatedRect(centre, w, h, 0), greyish(canvas, 0.75, 1.0));
    fillPolygon(canvas, rotatedRect(centre - cv::Point2f(0, h / 2 - h / 16), w, h / 8, 0),
                hsv(canvas.uniform(190, 240), 0.7, 0.7));
    for (int line = 1; line < 5; ++line) {
      drawText(canvas, centre + cv::Point2f(-w / 2.2f, -h / 2 + line * h / 5.5f), h / 9,
               greyish(canvas, 0.0, 0.3), 8);
    }
  }
}

void paintFabric(Canvas& canvas) {
  const cv::Scalar a = anyColour(canvas);
  const cv::Scalar b = anyColour(canvas);
  canvas.image.setTo(a);
  const double period = canvas.px(canvas.uniform(0.03, 0.08));
  for (double x = 0; x < canvas.image.cols; x += period) {
    cv::line(canvas.image, cv::Point(cvRound(x), 0), cv::Point(cvRound(x), canvas.image.rows), b,
             std::max(2, static_cast<int>(period / 4)), cv::LINE_AA);
  }
  for (double y = 0; y < canvas.image.rows; y += period * 1.3) {
    cv::line(canvas.image, cv::Point(0, cvRound(y)), cv::Point(canvas.image.cols, cvRound(y)), b,
             std::max(2, static_cast<int>(period / 5)), cv::LINE_AA);
  }
  addNoise(canvas, 8.0, {0.005, 0.03});
  scatterShapes(canvas, 30.0, 0.01, 0.06, [&] { return anyColour(canvas); });
}

void paintShirt(Canvas& canvas) {
  const cv::Scalar base = anyColour(canvas);
  const cv::Scalar stripe = anyColour(canvas);
  canvas.image.setTo(base);
  const double period = canvas.px(canvas.uniform(0.025, 0.07));
  const bool checks = canvas.chance(0.4);
  for (double y = 0; y < canvas.image.rows; y += period) {
    cv::rectangle(canvas.image, cv::Point(0, cvRound(y)),
                  cv::Point(canvas.image.cols, cvRound(y + period / 3)), stripe, cv::FILLED);
  }
  for (double x = 0; checks && x < canvas.image.cols; x += period) {
    cv::rectangle(canvas.image, cv::Point(cvRound(x), 0),
                  cv::Point(cvRound(x + period / 3), canvas.image.rows), stripe, cv::FILLED);
  }
  addNoise(canvas, 6.0, {0.005, 0.05});
  scatterShapes(canvas, 60.0, 0.01, 0.1, [&] { return anyColour(canvas); });
}

void paintTrousers(Canvas& canvas) {
  const int kind = canvas.uniformInt(0, 2);
  const cv::Scalar base = kind == 0 ? hsv(canvas.uniform(205, 225), 0.55, canvas.uniform(0.3, 0.5))
                          : kind == 1
                              ? greyish(canvas, 0.1, 0.25)
                              : hsv(canvas.uniform(30, 45), 0.35, canvas.uniform(0.45, 0.7));
  canvas.image.setTo(base);
  addNoise(canvas, 12.0, {0.003, 0.02}, 3.0);
  scatterShapes(canvas, 50.0, 0.008, 0.06, [&] { return greyish(canvas, 0.0, 1.0); });
}

void paintSkin(Canvas& canvas) {
  canvas.image.setTo(
      hsv(canvas.uniform(15, 30), canvas.uniform(0.3, 0.55), canvas.uniform(0.45, 0.9)));
  addNoise(canvas, 8.0, {0.005, 0.03});
  scatterShapes(canvas, 120.0, 0.005, 0.03, [&] {
    return hsv(canvas.uniform(10, 30), canvas.uniform(0.3, 0.7), canvas.uniform(0.05, 0.4));
  });
}

void paintShoes(Canvas& canvas) {
  canvas.image.setTo(greyish(canvas, 0.05, 0.3));
  addNoise(canvas, 5.0, {0.01});
  scatterShapes(canvas, 150.0, 0.008, 0.04, [&] { return greyish(canvas, 0.7, 1.0); });
}

}  // namespace

cv::Mat paintTexture(Material material, cv::Size size, double texel_size, std::uint64_t seed) {
  Canvas canvas{cv::Mat(std::max(size.height, 1), std::max(size.width, 1), CV_8UC3), texel_size,
                Rng(seed)};
  switch (material) {
    case Material::kWallpaper:
      paintWallpaper(canvas);
      break;
    case Material::kFloorPlanks:
      paintFloorPlanks(canvas);
      break;
    case Material::kCeilingTiles:
      paintCeilingTiles(canvas);
      break;
    case Material::kWood:
      paintWood(canvas);
      break;
    case Material::kLaminate:
      paintLaminate(canvas);
      break;
    case Material::kCardboard:
      paintCardboard(canvas);
      break;
    case Material::kBook:
      paintBook(canvas);
      break;
    case Material::kScreen:
      paintScreen(canvas);
      break;
    case Material::kFabric:
      paintFabric(canvas);
      break;
    case Material::kShirt:
      paintShirt(canvas);
      break;
    case Material::kTrousers:
      paintTrousers(canvas);
      break;
    case Material::kSkin:
      paintSkin(canvas);
      break;
    case Material::kShoes:
      paintShoes(canvas);
      break;
  }
  return canvas.image;
}

}  // namespace segslam::synth
