#pragma once

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/feature/scale_levels.h"
#include "segslam/geometry/pose.h"
#include "segslam/optim/rgbd_observation.h"

namespace segslam::map {

class KeyFrame;
class MapPoint;

// Keypoint indices bucketed by undistorted position, for fast "features near (u, v)" queries.
// The buckets share one array (cell by cell, each in keypoint order): every frame and keyframe
// has a grid, and a vector per cell cost a keyframe ~110 kB in 3072 small allocations.
class KeypointGrid {
 public:
  KeypointGrid() = default;
  KeypointGrid(const std::vector<cv::KeyPoint>& keypoints, const cv::Rect2d& bounds);

  // Indices of keypoints within `radius` pixels of (u, v) on pyramid levels [min_level, max_level]
  // (max_level < 0: no upper bound).
  [[nodiscard]] std::vector<std::size_t> featuresInArea(const std::vector<cv::KeyPoint>& keypoints,
                                                        double u, double v, double radius,
                                                        int min_level = 0,
                                                        int max_level = -1) const;
  [[nodiscard]] bool contains(double u, double v) const;

 private:
  static constexpr int kCols = 64;
  static constexpr int kRows = 48;
  cv::Rect2d bounds_;
  double cell_width_ = 1.0;
  double cell_height_ = 1.0;
  std::vector<std::uint32_t> cell_starts_;  // kCols * kRows + 1 offsets into indices_
  std::vector<std::uint32_t> indices_;
};

// ORB-SLAM2's TUM setting, bf = 40, as a baseline in metres at the 640x480 Kinect's fx of 525
// (7.6 cm, close to the real 7.5 cm). bf must follow fx: a fixed bf of 40 trusted depth out to
// 6.1 m on a 320x240 image (3.0 m on 640x480), so keyframes came only when tracking was nearly
// lost, and a synthetic 320x240 lap came out 9 % too large.
inline constexpr double kDefaultVirtualBaselineM = 40.0 / 525.0;

// The static description of the sensor that every frame shares.
struct FrameCamera {
  core::Camera camera;
  optim::StereoIntrinsics stereo;
  double close_depth_m = 3.0;     // depth below which a keypoint's depth is trusted for new points
  cv::Rect2d undistorted_bounds;  // image area after undistortion
  feature::ScaleLevels levels;
  // Where each undistorted pixel lies in the raw image (CV_32FC2), to compare map points with the
  // raw depth image; empty when the camera has no distortion.
  cv::Mat raw_pixel_of_undistorted;

  // `baseline_m`: the virtual stereo baseline in metres. bf is fx times it and the close depth
  // `close_depth_baselines` times it, so both describe the same sensor at any image size.
  FrameCamera(const core::Camera& camera, double baseline_m, double close_depth_baselines,
              const feature::ScaleLevels& levels);
};

// One RGB-D image reduced to what tracking needs: keypoints (raw and undistorted), their depth
// and virtual right coordinate, descriptors, and the map points they were matched to.
class Frame {
 public:
  Frame() = default;
  // depth_m: CV_32F metres, registered to the colour image (0 = no measurement).
  // dynamic_mask: empty or CV_8U, non-zero where something moves (already dilated).
  Frame(std::uint64_t id, double timestamp, std::vector<cv::KeyPoint> keypoints,
        cv::Mat descriptors, const cv::Mat& depth_m, cv::Mat dynamic_mask,
        std::shared_ptr<const FrameCamera> camera);

  [[nodiscard]] std::size_t size() const { return keypoints.size(); }
  [[nodiscard]] optim::RgbdObservation observation(std::size_t i) const;
  // Camera-frame point of keypoint i from its depth (requires depth[i] > 0).
  [[nodiscard]] Eigen::Vector3d unproject(std::size_t i) const;
  // True when the undistorted pixel lies in a dynamic area of this frame.
  [[nodiscard]] bool isDynamicAt(double u, double v) const;
  [[nodiscard]] Eigen::Vector3d cameraCentre() const { return T_cw.inverse().translation(); }
  // A rolling-shutter camera reads each row at another moment: moves every undistorted keypoint,
  // and its depth, to where the camera saw it at the middle row's moment, the one its pose is
  // for. `motion` maps camera coordinates at one moment to those `motion_dt` seconds later (the
  // camera's motion between two frames); `readout_s` is the time from the first row to the last
  // (negative: the last row read first). Each call starts again from the keypoints as read, so a
  // better motion or readout estimate can replace a first one. Also sets readout_gradient.
  void compensateRollingShutter(const geometry::Pose& motion, double motion_dt, double readout_s);

  std::uint64_t id = 0;
  double timestamp = 0.0;
  std::shared_ptr<const FrameCamera> camera;
  std::vector<cv::KeyPoint> keypoints;     // as detected (distorted image)
  std::vector<cv::KeyPoint> keypoints_un;  // undistorted
  std::vector<float> depth;                // metres, <= 0: none
  std::vector<float> right_u;              // virtual right column, < 0: none
  cv::Mat descriptors;                     // N x 32, CV_8U
  cv::Mat dynamic_mask;
  cv::Mat depth_image;  // CV_32F metres, shared with the caller (not copied)
  // Per undistorted keypoint, after compensateRollingShutter: how far it moves per second of
  // readout (pixels per second), what estimating the readout needs. Empty before.
  std::vector<Eigen::Vector2d> readout_gradient;
  // The colour image (CV_8UC3), set only when a keyframe made from this frame needs it later (the
  // CNN loop detector); shared, not copied.
  cv::Mat image;
  KeypointGrid grid;

  std::vector<std::shared_ptr<MapPoint>> map_points;  // match per keypoint, may be null
  std::vector<bool> outlier;

  geometry::Pose T_cw = geometry::Pose::Identity();  // world-to-camera
  bool has_pose = false;
  std::shared_ptr<KeyFrame> reference_keyframe;

 private:
  // Undistorted keypoints and their depth as the sensor read them, kept once compensated.
  std::vector<cv::Point2f> read_points_;
  std::vector<float> read_depth_;
};

}  // namespace segslam::map
