#include "segslam/map/frame.h"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>

#include "segslam/core/undistortion.h"

namespace segslam::map {

namespace {

cv::Rect2d undistortedBounds(const core::Camera& camera) {
  const float w = static_cast<float>(camera.width);
  const float h = static_cast<float>(camera.height);
  const auto corners = core::undistortPixels({{0, 0}, {w, 0}, {0, h}, {w, h}}, camera);
  const double min_x = std::min(corners[0].x, corners[2].x);
  const double max_x = std::max(corners[1].x, corners[3].x);
  const double min_y = std::min(corners[0].y, corners[1].y);
  const double max_y = std::max(corners[2].y, corners[3].y);
  return {min_x, min_y, max_x - min_x, max_y - min_y};
}

}  // namespace

KeypointGrid::KeypointGrid(const std::vector<cv::KeyPoint>& keypoints, const cv::Rect2d& bounds)
    : bounds_(bounds),
      cell_width_(bounds.width / kCols),
      cell_height_(bounds.height / kRows),
      cell_starts_(kCols * kRows + 1, 0) {
  std::vector<int> cell_of(keypoints.size(), -1);
  for (std::size_t i = 0; i < keypoints.size(); ++i) {
    const int col = static_cast<int>((keypoints[i].pt.x - bounds_.x) / cell_width_);
    const int row = static_cast<int>((keypoints[i].pt.y - bounds_.y) / cell_height_);
    if (col < 0 || col >= kCols || row < 0 || row >= kRows) continue;
    cell_of[i] = row * kCols + col;
    ++cell_starts_[cell_of[i] + 1];
  }
  for (std::size_t cell = 1; cell < cell_starts_.size(); ++cell) {
    cell_starts_[cell] += cell_starts_[cell - 1];
  }
  indices_.resize(cell_starts_.back());
  std::vector<std::uint32_t> next(cell_starts_.begin(), cell_starts_.end() - 1);
  for (std::size_t i = 0; i < keypoints.size(); ++i) {
    if (cell_of[i] >= 0) indices_[next[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  }
}

bool KeypointGrid::contains(double u, double v) const {
  return u >= bounds_.x && u < bounds_.x + bounds_.width && v >= bounds_.y &&
         v < bounds_.y + bounds_.height;
}

std::vector<std::size_t> KeypointGrid::featuresInArea(const std::vector<cv::KeyPoint>& keypoints,
                                                      double u, double v, double radius,
                                                      int min_level, int max_level) const {
  std::vector<std::size_t> found;
  if (cell_starts_.empty()) return found;
  const int col_min = std::max(0, static_cast<int>((u - radius - bounds_.x) / cell_width_));
  const int col_max = std::min(kCols - 1, static_cast<int>((u + radius - bounds_.x) / cell_width_));
  const int row_min = std::max(0, static_cast<int>((v - radius - bounds_.y) / cell_height_));
  const int row_max =
      std::min(kRows - 1, static_cast<int>((v + radius - bounds_.y) / cell_height_));
  if (col_min > col_max || row_min > row_max) return found;
  const double radius2 = radius * radius;
  for (int row = row_min; row <= row_max; ++row) {
    for (int col = col_min; col <= col_max; ++col) {
      const int cell = row * kCols + col;
      for (std::uint32_t k = cell_starts_[cell]; k < cell_starts_[cell + 1]; ++k) {
        const std::size_t i = indices_[k];
        const cv::KeyPoint& kp = keypoints[i];
        if (kp.octave < min_level || (max_level >= 0 && kp.octave > max_level)) continue;
        const double du = kp.pt.x - u;
        const double dv = kp.pt.y - v;
        if (du * du + dv * dv < radius2) found.push_back(i);
      }
    }
  }
  return found;
}

FrameCamera::FrameCamera(const core::Camera& cam, double baseline_m, double close_depth_baselines,
                         const feature::ScaleLevels& scale_levels)
    : camera(cam),
      stereo{cam.fx, cam.fy, cam.cx, cam.cy, cam.fx * baseline_m},
      close_depth_m(close_depth_baselines * baseline_m),
      undistorted_bounds(undistortedBounds(cam)),
      levels(scale_levels) {
  if (!cam.hasDistortion()) return;
  cv::Mat unused;
  const cv::Mat K = core::cameraMatrix(cam);
  cv::initUndistortRectifyMap(K, cv::Mat(1, 5, CV_64F, const_cast<double*>(cam.distortion.data())),
                              cv::Mat(), K, cv::Size(cam.width, cam.height), CV_32FC2,
                              raw_pixel_of_undistorted, unused);
}

Frame::Frame(std::uint64_t frame_id, double stamp, std::vector<cv::KeyPoint> raw_keypoints,
             cv::Mat frame_descriptors, const cv::Mat& depth_m, cv::Mat mask,
             std::shared_ptr<const FrameCamera> frame_camera)
    : id(frame_id),
      timestamp(stamp),
      camera(std::move(frame_camera)),
      keypoints(std::move(raw_keypoints)),
      descriptors(std::move(frame_descriptors)),
      dynamic_mask(std::move(mask)),
      depth_image(depth_m) {
  std::vector<cv::Point2f> points;
  points.reserve(keypoints.size());
  for (const auto& kp : keypoints) points.push_back(kp.pt);
  const auto undistorted = core::undistortPixels(points, camera->camera);
  keypoints_un = keypoints;
  depth.assign(keypoints.size(), -1.0f);
  right_u.assign(keypoints.size(), -1.0f);
  for (std::size_t i = 0; i < keypoints.size(); ++i) {
    keypoints_un[i].pt = undistorted[i];
    const int u = static_cast<int>(std::lround(keypoints[i].pt.x));
    const int v = static_cast<int>(std::lround(keypoints[i].pt.y));
    if (u < 0 || v < 0 || u >= depth_m.cols || v >= depth_m.rows) continue;
    const float z = depth_m.at<float>(v, u);
    if (z > 0.0f) {
      depth[i] = z;
      right_u[i] = keypoints_un[i].pt.x - static_cast<float>(camera->stereo.bf / z);
    }
  }
  grid = KeypointGrid(keypoints_un, camera->undistorted_bounds);
  map_points.assign(keypoints.size(), nullptr);
  outlier.assign(keypoints.size(), false);
}

optim::RgbdObservation Frame::observation(std::size_t i) const {
  const auto& kp = keypoints_un[i];
  return {{kp.pt.x, kp.pt.y}, right_u[i], camera->levels.inverseSigma2()[kp.octave]};
}

void Frame::compensateRollingShutter(const geometry::Pose& motion, double motion_dt,
                                     double readout_s) {
  if (motion_dt <= 0.0) return;
  const core::Camera& cam = camera->camera;
  if (read_points_.empty()) {
    read_points_.reserve(keypoints_un.size());
    for (const auto& kp : keypoints_un) read_points_.push_back(kp.pt);
    read_depth_ = depth;
  }
  // The motion over a fraction of a frame is small: first order in its rotation is exact to
  // well below a pixel.
  const Eigen::AngleAxisd rotation(motion.rotation());
  const Eigen::Vector3d rotation_rate = rotation.angle() * rotation.axis() / motion_dt;
  const Eigen::Vector3d translation_rate = motion.translation() / motion_dt;
  const double middle_row = 0.5 * cam.height;
  readout_gradient.assign(keypoints.size(), Eigen::Vector2d::Zero());
  for (std::size_t i = 0; i < keypoints.size(); ++i) {
    // The sensor's row is the raw (distorted) one: its share of the readout from the middle row.
    const double row_share = (keypoints[i].pt.y - middle_row) / cam.height;
    const cv::Point2f& read = read_points_[i];
    const bool has_depth = read_depth_[i] > 0.0f;
    // Without depth the point is taken as far away: only the rotation moves it.
    const Eigen::Vector3d seen = cam.backProject(read.x, read.y, has_depth ? read_depth_[i] : 1.0);
    // The point's velocity in camera coordinates, d(moved)/d(dt) with a minus sign.
    const Eigen::Vector3d drift =
        rotation_rate.cross(seen) + (has_depth ? translation_rate : Eigen::Vector3d::Zero());
    const Eigen::Vector3d moved = seen - drift * (row_share * readout_s);
    if (moved.z() <= 0.0) continue;
    const Eigen::Vector2d uv = cam.project(moved);
    keypoints_un[i].pt = cv::Point2f(static_cast<float>(uv.x()), static_cast<float>(uv.y()));
    const Eigen::Vector3d moved_per_readout = -row_share * drift;
    const double inverse_z = 1.0 / moved.z();
    readout_gradient[i] = Eigen::Vector2d(
        cam.fx * inverse_z *
            (moved_per_readout.x() - moved.x() * inverse_z * moved_per_readout.z()),
        cam.fy * inverse_z *
            (moved_per_readout.y() - moved.y() * inverse_z * moved_per_readout.z()));
    if (!has_depth) continue;
    depth[i] = static_cast<float>(moved.z());
    right_u[i] = keypoints_un[i].pt.x - static_cast<float>(camera->stereo.bf / depth[i]);
  }
  grid = KeypointGrid(keypoints_un, camera->undistorted_bounds);
}

Eigen::Vector3d Frame::unproject(std::size_t i) const {
  return camera->camera.backProject(keypoints_un[i].pt.x, keypoints_un[i].pt.y, depth[i]);
}

bool Frame::isDynamicAt(double u, double v) const {
  if (dynamic_mask.empty()) return false;
  const int x = static_cast<int>(std::lround(u));
  const int y = static_cast<int>(std::lround(v));
  if (x < 0 || y < 0 || x >= dynamic_mask.cols || y >= dynamic_mask.rows) return false;
  return dynamic_mask.at<std::uint8_t>(y, x) != 0;
}

}  // namespace segslam::map
