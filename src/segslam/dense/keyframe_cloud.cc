#include "segslam/dense/keyframe_cloud.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "segslam/core/undistortion.h"
#include "segslam/feature/static_mask.h"

namespace segslam::dense {

namespace {

cv::Mat normalisedPixelTable(const core::Camera& camera) {
  std::vector<cv::Point2f> pixels;
  pixels.reserve(static_cast<std::size_t>(camera.width) * camera.height);
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) pixels.emplace_back(u, v);
  }
  if (camera.hasDistortion()) pixels = core::undistortPixels(pixels, camera);
  cv::Mat table(camera.height, camera.width, CV_32FC2);
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const cv::Point2f& p = pixels[static_cast<std::size_t>(v) * camera.width + u];
      table.at<cv::Vec2f>(v, u) = {static_cast<float>((p.x - camera.cx) / camera.fx),
                                   static_cast<float>((p.y - camera.cy) / camera.fy)};
    }
  }
  return table;
}

void requireImage(const cv::Mat& image, int type, cv::Size size, const std::string& what,
                  bool optional) {
  if (optional && image.empty()) return;
  if (image.type() != type || image.size() != size) {
    throw std::invalid_argument("KeyFrameCloudMaker: " + what +
                                " image has the wrong type or size");
  }
}

// Neighbouring samples at depth z are stride * z / f apart.
int strideFor(const core::Camera& camera, const KeyFrameCloudOptions& options) {
  if (!(options.full_sampling_depth > 0.0)) return 1;
  const double focal = std::min(camera.fx, camera.fy);
  const double stride = std::floor(options.voxel_size * focal / options.full_sampling_depth);
  return static_cast<int>(std::clamp(stride, 1.0, 64.0));
}

}  // namespace

KeyFrameCloudMaker::KeyFrameCloudMaker(const core::Camera& camera, KeyFrameCloudOptions options)
    : camera_(camera),
      options_(options),
      stride_(strideFor(camera, options)),
      normalised_(normalisedPixelTable(camera)) {
  if (!(options_.voxel_size > 0.0)) {
    throw std::invalid_argument("KeyFrameCloudMaker: voxel size must be > 0");
  }
}

bool KeyFrameCloudMaker::onDepthEdge(const cv::Mat& depth, int row, int col) const {
  const float z = depth.at<float>(row, col);
  const float limit = static_cast<float>(options_.depth_edge_ratio) * z;
  const int offsets[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  for (const auto& [dr, dc] : offsets) {
    const int r = row + dr;
    const int c = col + dc;
    if (r < 0 || c < 0 || r >= depth.rows || c >= depth.cols) continue;
    const float neighbour = depth.at<float>(r, c);
    if (neighbour > 0.0f && std::abs(neighbour - z) > limit) return true;
  }
  return false;
}

KeyFrameCloud KeyFrameCloudMaker::make(const KeyFrameImages& images) const {
  return downsample(backProject(images));
}

KeyFrameCloud KeyFrameCloudMaker::downsample(const KeyFrameCloud& cloud) const {
  return {voxelDownsample(cloud.static_points, options_.voxel_size),
          voxelDownsample(cloud.dynamic_points, options_.voxel_size),
          voxelDownsample(cloud.folded_points, options_.voxel_size)};
}

KeyFrameCloud KeyFrameCloudMaker::backProject(const KeyFrameImages& images) const {
  const cv::Size size(camera_.width, camera_.height);
  requireImage(images.bgr, CV_8UC3, size, "colour", false);
  requireImage(images.depth, CV_32FC1, size, "depth", false);
  requireImage(images.dynamic_mask, CV_8UC1, size, "dynamic mask", true);
  requireImage(images.labels, CV_8UC1, size, "label", true);
  requireImage(images.instances, CV_16UC1, size, "instance", true);
  const cv::Mat dilated =
      feature::dilateDynamicMask(images.dynamic_mask, options_.mask_dilation_px);

  KeyFrameCloud cloud;
  // One allocation of the most a keyframe can give rather than a vector doubled ~17 times: the
  // map thread makes a cloud every keyframe, and the ladder of freed sizes fragmented its heap.
  cloud.static_points.reserve(static_cast<std::size_t>((size.height + stride_ - 1) / stride_) *
                              ((size.width + stride_ - 1) / stride_));
  const auto max_depth = static_cast<float>(options_.max_depth);
  for (int v = 0; v < size.height; v += stride_) {
    const auto* depth_row = images.depth.ptr<float>(v);
    const auto* colour_row = images.bgr.ptr<cv::Vec3b>(v);
    const auto* xy_row = normalised_.ptr<cv::Vec2f>(v);
    for (int u = 0; u < size.width; u += stride_) {
      const float z = depth_row[u];
      if (!(z > 0.0f) || !(z <= max_depth) || onDepthEdge(images.depth, v, u)) continue;
      const bool dynamic =
          !images.dynamic_mask.empty() && images.dynamic_mask.at<std::uint8_t>(v, u) != 0;
      const bool near_dynamic = dynamic || (!dilated.empty() && dilated.at<std::uint8_t>(v, u));
      if (near_dynamic && !dynamic) continue;
      const cv::Vec3b& bgr = colour_row[u];
      const std::uint8_t label = images.labels.empty() ? 0 : images.labels.at<std::uint8_t>(v, u);
      const std::uint16_t instance =
          images.instances.empty() ? 0 : images.instances.at<std::uint16_t>(v, u);
      (dynamic ? cloud.dynamic_points : cloud.static_points)
          .add({xy_row[u][0] * z, xy_row[u][1] * z, z}, {bgr[2], bgr[1], bgr[0]}, label, instance);
    }
  }
  return cloud;
}

}  // namespace segslam::dense
