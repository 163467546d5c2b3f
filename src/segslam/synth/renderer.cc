#include "segslam/synth/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "segslam/synth/screen_bounds.h"

namespace segslam::synth {

namespace {

constexpr double kNearZ = 0.01;
constexpr float kAmbient = 0.62f;
constexpr int kRowsPerTask = 4;
// Slanted surfaces get a larger texture footprint, but only by the square root of the slant:
// a compromise between aliasing along the slant and blurring across it.
constexpr double kMinFootprintCosine = 0.05;

float lambert(const Eigen::Vector3d& normal_w) {
  static const Eigen::Vector3d kLight = Eigen::Vector3d(0.35, 0.45, 1.0).normalized();
  return kAmbient + (1.0f - kAmbient) * static_cast<float>(std::max(0.0, normal_w.dot(kLight)));
}

// Normalised image coordinates of every pixel column and row.
struct RayGrid {
  std::vector<double> x;  // (u - cx) / fx
  std::vector<double> y;  // (v - cy) / fy

  explicit RayGrid(const core::Camera& camera) : x(camera.width), y(camera.height) {
    for (int u = 0; u < camera.width; ++u) x[u] = (u - camera.cx) / camera.fx;
    for (int v = 0; v < camera.height; ++v) y[v] = (v - camera.cy) / camera.fy;
  }
};

// A rectangle in the camera frame, ready for per-pixel ray intersection.
struct RectSetup {
  Eigen::Vector3d normal;
  double plane = 0.0;  // normal . origin; negative when the front side faces the camera
  Eigen::Vector3d axis_u;
  Eigen::Vector3d axis_v;
  double offset_u = 0.0;  // axis_u . origin
  double offset_v = 0.0;
  float shade = 1.0f;
  PixelBox box;
  const TexturedRect* source = nullptr;
};

// An ellipsoid mapped to the unit sphere: a camera ray d becomes origin + z * to_unit * d.
struct EllipsoidSetup {
  Eigen::Matrix3d to_unit;
  Eigen::Vector3d origin;
  double origin_term = 0.0;  // |origin|^2 - 1, positive when the camera is outside
  Eigen::Matrix3d normal_to_world;
  PixelBox box;
  const TexturedEllipsoid* source = nullptr;
};

struct Setups {
  std::vector<RectSetup> rects;
  std::vector<EllipsoidSetup> ellipsoids;
};

// Nearest hit per pixel: depth and primitive (rect setup index, or rects.size() + ellipsoid setup
// index; -1 for none).
struct Hits {
  std::vector<double> z;
  std::vector<std::int32_t> primitive;
};

std::optional<RectSetup> setupRect(const TexturedRect& rect, const geometry::Pose& T_cw,
                                   const core::Camera& camera) {
  RectSetup setup;
  const Rect in_camera = transformed(T_cw, rect.shape);
  setup.normal = in_camera.normal();
  setup.plane = setup.normal.dot(in_camera.origin);
  if (setup.plane >= 0.0) return std::nullopt;  // back side or edge-on
  const auto corners = in_camera.corners();
  setup.box = screenBounds(corners, quadEdges(), camera, kNearZ);
  if (setup.box.empty()) return std::nullopt;
  setup.axis_u = in_camera.axis_u;
  setup.axis_v = in_camera.axis_v;
  setup.offset_u = setup.axis_u.dot(in_camera.origin);
  setup.offset_v = setup.axis_v.dot(in_camera.origin);
  setup.shade = lambert(rect.shape.normal());
  setup.source = &rect;
  return setup;
}

std::optional<EllipsoidSetup> setupEllipsoid(const TexturedEllipsoid& ellipsoid,
                                             const geometry::Pose& T_cw,
                                             const core::Camera& camera) {
  const Ellipsoid in_camera = transformed(T_cw, ellipsoid.shape);
  const auto corners = in_camera.boxCorners();
  EllipsoidSetup setup;
  setup.box = screenBounds(corners, boxEdges(), camera, kNearZ);
  if (setup.box.empty()) return std::nullopt;
  const Eigen::Vector3d inverse_radii = in_camera.radii.cwiseInverse();
  setup.to_unit = inverse_radii.asDiagonal() * in_camera.axes.transpose();
  setup.origin = -(setup.to_unit * in_camera.center);
  setup.origin_term = setup.origin.squaredNorm() - 1.0;
  if (setup.origin_term <= 0.0) return std::nullopt;  // camera inside: cannot be seen properly
  setup.normal_to_world = ellipsoid.shape.axes * inverse_radii.asDiagonal();
  setup.source = &ellipsoid;
  return setup;
}

Setups setupScene(const RenderScene& scene, const geometry::Pose& T_wc,
                  const core::Camera& camera) {
  const geometry::Pose T_cw = T_wc.inverse();
  Setups setups;
  for (const auto& rect : scene.rects) {
    if (auto setup = setupRect(rect, T_cw, camera)) setups.rects.push_back(*setup);
  }
  for (const auto& ellipsoid : scene.ellipsoids) {
    if (auto setup = setupEllipsoid(ellipsoid, T_cw, camera)) setups.ellipsoids.push_back(*setup);
  }
  return setups;
}

void rasteriseRect(const RectSetup& rect, std::int32_t id, int row_begin, int row_end,
                   const RayGrid& rays, Hits& hits) {
  const int width = static_cast<int>(rays.x.size());
  const double size_u = rect.source->shape.size_u;
  const double size_v = rect.source->shape.size_v;
  for (int v = std::max(row_begin, rect.box.v0); v <= std::min(row_end - 1, rect.box.v1); ++v) {
    const double y = rays.y[v];
    const double denom_row = rect.normal.y() * y + rect.normal.z();
    const double u_row = rect.axis_u.y() * y + rect.axis_u.z();
    const double v_row = rect.axis_v.y() * y + rect.axis_v.z();
    for (int u = rect.box.u0; u <= rect.box.u1; ++u) {
      const double x = rays.x[u];
      const double denom = rect.normal.x() * x + denom_row;
      if (denom >= 0.0) continue;
      const double z = rect.plane / denom;
      const std::size_t index = static_cast<std::size_t>(v) * width + u;
      if (z <= kNearZ || z >= hits.z[index]) continue;
      const double s = z * (rect.axis_u.x() * x + u_row) - rect.offset_u;
      if (s < 0.0 || s > size_u) continue;
      const double t = z * (rect.axis_v.x() * x + v_row) - rect.offset_v;
      if (t < 0.0 || t > size_v) continue;
      hits.z[index] = z;
      hits.primitive[index] = id;
    }
  }
}

void rasteriseEllipsoid(const EllipsoidSetup& ellipsoid, std::int32_t id, int row_begin,
                        int row_end, const RayGrid& rays, Hits& hits) {
  const int width = static_cast<int>(rays.x.size());
  const Eigen::Vector3d column_step = ellipsoid.to_unit.col(0);
  for (int v = std::max(row_begin, ellipsoid.box.v0); v <= std::min(row_end - 1, ellipsoid.box.v1);
       ++v) {
    const Eigen::Vector3d row_part =
        ellipsoid.to_unit.col(1) * rays.y[v] + ellipsoid.to_unit.col(2);
    for (int u = ellipsoid.box.u0; u <= ellipsoid.box.u1; ++u) {
      const Eigen::Vector3d direction = column_step * rays.x[u] + row_part;
      const double a = direction.squaredNorm();
      const double half_b = ellipsoid.origin.dot(direction);
      const double discriminant = half_b * half_b - a * ellipsoid.origin_term;
      if (discriminant < 0.0) continue;
      const double z = (-half_b - std::sqrt(discriminant)) / a;
      const std::size_t index = static_cast<std::size_t>(v) * width + u;
      if (z <= kNearZ || z >= hits.z[index]) continue;
      hits.z[index] = z;
      hits.primitive[index] = id;
    }
  }
}

Hits findNearestHits(const Setups& setups, const RayGrid& rays) {
  const std::size_t pixels = rays.x.size() * rays.y.size();
  Hits hits{std::vector<double>(pixels, std::numeric_limits<double>::infinity()),
            std::vector<std::int32_t>(pixels, -1)};
  const auto rect_count = static_cast<std::int32_t>(setups.rects.size());
  const int height = static_cast<int>(rays.y.size());
  tbb::parallel_for(
      tbb::blocked_range<int>(0, height, kRowsPerTask), [&](const tbb::blocked_range<int>& rows) {
        for (std::int32_t i = 0; i < rect_count; ++i) {
          rasteriseRect(setups.rects[i], i, rows.begin(), rows.end(), rays, hits);
        }
        for (std::size_t i = 0; i < setups.ellipsoids.size(); ++i) {
          rasteriseEllipsoid(setups.ellipsoids[i], rect_count + static_cast<std::int32_t>(i),
                             rows.begin(), rows.end(), rays, hits);
        }
      });
  return hits;
}

// Colour and surface of a hit, from the primitive's texture and shading.
struct Shaded {
  Eigen::Vector3f colour;
  const SurfaceInfo* surface;
};

Shaded shadeRect(const RectSetup& rect, const Eigen::Vector3d& ray, double z, double fx) {
  const Eigen::Vector3d point = z * ray;
  const double s = rect.axis_u.dot(point) - rect.offset_u;
  const double t = rect.axis_v.dot(point) - rect.offset_v;
  const double ray_length = ray.norm();
  const double cosine = std::abs(rect.normal.dot(ray)) / ray_length;
  const double footprint = z * ray_length / (fx * std::sqrt(std::max(cosine, kMinFootprintCosine)));
  const SurfaceInfo& surface = rect.source->surface;
  return {surface.texture->sample(s, t, footprint) * rect.shade, &surface};
}

Shaded shadeEllipsoid(const EllipsoidSetup& ellipsoid, const Eigen::Vector3d& ray, double z,
                      double fx) {
  const Eigen::Vector3d on_sphere = ellipsoid.origin + z * (ellipsoid.to_unit * ray);
  const Eigen::Vector3d& radii = ellipsoid.source->shape.radii;
  const double longitude = std::atan2(on_sphere.y(), on_sphere.x());
  const double s = (longitude + std::numbers::pi) * 0.5 * (radii.x() + radii.y());
  const double t = (on_sphere.z() + 1.0) * radii.z();
  const double footprint = z * ray.norm() / fx;
  const float shade = lambert((ellipsoid.normal_to_world * on_sphere).normalized());
  const SurfaceInfo& surface = ellipsoid.source->surface;
  return {surface.texture->sample(s, t, footprint) * shade, &surface};
}

cv::Vec3b toPixel(const Eigen::Vector3f& colour) {
  cv::Vec3b pixel;
  for (int c = 0; c < 3; ++c) pixel[c] = cv::saturate_cast<std::uint8_t>(colour[c]);
  return pixel;
}

struct ShadedImages {
  FrameImages images;
  cv::Mat exact_z;  // CV_64FC1
};

void shadeRow(int v, const Setups& setups, const Hits& hits, const RayGrid& rays, double fx,
              ShadedImages& out) {
  const int width = static_cast<int>(rays.x.size());
  auto* rgb = out.images.rgb.ptr<cv::Vec3b>(v);
  auto* labels = out.images.labels.ptr<std::uint8_t>(v);
  auto* instances = out.images.instances.ptr<std::uint16_t>(v);
  auto* mask = out.images.mask.ptr<std::uint8_t>(v);
  auto* exact_z = out.exact_z.ptr<double>(v);
  for (int u = 0; u < width; ++u) {
    const std::size_t index = static_cast<std::size_t>(v) * width + u;
    const std::int32_t id = hits.primitive[index];
    if (id < 0) continue;
    const double z = hits.z[index];
    const Eigen::Vector3d ray(rays.x[u], rays.y[v], 1.0);
    const auto rect_count = static_cast<std::int32_t>(setups.rects.size());
    const Shaded shaded = id < rect_count
                              ? shadeRect(setups.rects[id], ray, z, fx)
                              : shadeEllipsoid(setups.ellipsoids[id - rect_count], ray, z, fx);
    rgb[u] = toPixel(shaded.colour);
    labels[u] = static_cast<std::uint8_t>(shaded.surface->semantic_class);
    instances[u] = shaded.surface->instance;
    mask[u] = shaded.surface->dynamic ? 255 : 0;
    exact_z[u] = z;
  }
}

ShadedImages shade(const Setups& setups, const Hits& hits, const RayGrid& rays,
                   const core::Camera& camera) {
  const cv::Size size(camera.width, camera.height);
  ShadedImages out{{cv::Mat::zeros(size, CV_8UC3), cv::Mat(), cv::Mat::zeros(size, CV_8UC1),
                    cv::Mat::zeros(size, CV_16UC1), cv::Mat::zeros(size, CV_8UC1)},
                   cv::Mat::zeros(size, CV_64FC1)};
  tbb::parallel_for(tbb::blocked_range<int>(0, camera.height, kRowsPerTask),
                    [&](const tbb::blocked_range<int>& rows) {
                      for (int v = rows.begin(); v != rows.end(); ++v) {
                        shadeRow(v, setups, hits, rays, camera.fx, out);
                      }
                    });
  return out;
}

}  // namespace

FrameImages renderFrame(const RenderScene& scene, const core::Camera& camera,
                        const geometry::Pose& T_wc, DepthNoise depth_noise,
                        std::uint64_t noise_seed) {
  const RayGrid rays(camera);
  const Setups setups = setupScene(scene, T_wc, camera);
  const Hits hits = findNearestHits(setups, rays);
  ShadedImages shaded = shade(setups, hits, rays, camera);
  shaded.images.depth = depthImage(shaded.exact_z, depth_noise, camera.depth_factor, noise_seed);
  return shaded.images;
}

}  // namespace segslam::synth
