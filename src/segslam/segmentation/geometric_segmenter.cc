#include "segslam/segmentation/geometric_segmenter.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <vector>

#include "segslam/core/undistortion.h"

namespace segslam::segmentation {

namespace {

constexpr int kMinStaticCorrespondences = 12;

float depthAt(const cv::Mat& depth, const cv::Point2f& p) {
  const int x = cvRound(p.x);
  const int y = cvRound(p.y);
  if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) return 0.0f;
  return depth.at<float>(y, x);
}

bool isMarked(const cv::Mat& mask, const cv::Point2f& p) {
  if (mask.empty()) return false;
  const int x = cvRound(p.x);
  const int y = cvRound(p.y);
  return x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<std::uint8_t>(y, x) != 0;
}

// Corners of `current` and where they were in `previous` (raw pixels), tracked ones only.
struct Tracks {
  std::vector<cv::Point2f> current;
  std::vector<cv::Point2f> previous;
};

// Lucas-Kanade tracks that do not come back to where they started (occlusion, blur, repeated
// texture) would look like motion; they are dropped.
constexpr float kMaxForwardBackwardPx = 1.0f;

Tracks trackCorners(const DepthFrame& previous, const DepthFrame& current, int max_corners) {
  Tracks tracks;
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(current.gray, corners, max_corners, 0.01, 10.0);
  if (corners.empty()) return tracks;
  std::vector<cv::Point2f> back;
  std::vector<cv::Point2f> forth;
  std::vector<std::uint8_t> status;
  std::vector<std::uint8_t> status_forth;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(current.gray, previous.gray, corners, back, status, error,
                           cv::Size(21, 21), 3);
  cv::calcOpticalFlowPyrLK(previous.gray, current.gray, back, forth, status_forth, error,
                           cv::Size(21, 21), 3);
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (!status[i] || !status_forth[i]) continue;
    if (cv::norm(forth[i] - corners[i]) > kMaxForwardBackwardPx) continue;
    tracks.current.push_back(corners[i]);
    tracks.previous.push_back(back[i]);
  }
  return tracks;
}

}  // namespace

GeometricSegmenter::GeometricSegmenter(const core::Camera& camera, GeometricOptions options)
    : camera_(camera), options_(options) {}

cv::Mat GeometricSegmenter::segment(const DepthFrame& previous, const DepthFrame& current,
                                    const cv::Mat& known_dynamic) const {
  const Tracks tracks = trackCorners(previous, current, options_.max_corners);
  const auto previous_un = core::undistortPixels(tracks.previous, camera_);
  const auto current_un = core::undistortPixels(tracks.current, camera_);

  // 3D points of the previous frame with their current pixels; static candidates for the pose.
  std::vector<cv::Point3f> points;
  std::vector<cv::Point2f> pixels;
  std::vector<std::size_t> track_of;
  std::vector<cv::Point3f> static_points;
  std::vector<cv::Point2f> static_pixels;
  for (std::size_t i = 0; i < tracks.current.size(); ++i) {
    const float z = depthAt(previous.depth, tracks.previous[i]);
    if (z <= 0.0f) continue;
    const Eigen::Vector3d p = camera_.backProject(previous_un[i].x, previous_un[i].y, z);
    points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                        static_cast<float>(p.z()));
    pixels.push_back(current_un[i]);
    track_of.push_back(i);
    if (!isMarked(known_dynamic, tracks.current[i])) {
      static_points.push_back(points.back());
      static_pixels.push_back(current_un[i]);
    }
  }
  if (static_points.size() < static_cast<std::size_t>(kMinStaticCorrespondences)) return {};
  cv::Mat rvec;
  cv::Mat tvec;
  const cv::Mat k = core::cameraMatrix(camera_);
  if (!cv::solvePnPRansac(static_points, static_pixels, k, cv::noArray(), rvec, tvec, false, 100,
                          static_cast<float>(options_.reprojection_px) * 0.7f, 0.99)) {
    return {};
  }

  // Seeds: corners whose image position or depth the camera motion does not explain.
  std::vector<cv::Point2f> predicted;
  cv::projectPoints(points, rvec, tvec, k, cv::noArray(), predicted);
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  std::vector<cv::Point> seeds;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const cv::Mat p = rotation * cv::Mat(cv::Vec3d(points[j].x, points[j].y, points[j].z)) + tvec;
    const double z_predicted = p.at<double>(2);
    const float z_observed = depthAt(current.depth, tracks.current[track_of[j]]);
    const bool image_motion = cv::norm(predicted[j] - pixels[j]) > options_.reprojection_px;
    const bool depth_motion = z_observed > 0.0f && std::abs(z_predicted - z_observed) >
                                                       options_.depth_tolerance * z_observed;
    if (image_motion || depth_motion) seeds.push_back(tracks.current[track_of[j]]);
  }
  return growObjects(current.depth, seeds);
}

cv::Mat GeometricSegmenter::growObjects(const cv::Mat& depth,
                                        const std::vector<cv::Point>& seeds) const {
  cv::Mat dynamic = cv::Mat::zeros(depth.size(), CV_8UC1);
  cv::Mat visited = cv::Mat::zeros(depth.size(), CV_8UC1);
  const double max_area = options_.max_object_share * static_cast<double>(depth.total());
  cv::Mat depth_copy = depth.clone();
  for (const cv::Point& seed : seeds) {
    if (visited.at<std::uint8_t>(seed) != 0) continue;
    const float z = depth.at<float>(seed);
    if (z <= 0.0f) continue;
    cv::Mat region = cv::Mat::zeros(depth.rows + 2, depth.cols + 2, CV_8UC1);
    const float range = static_cast<float>(options_.region_depth_range_m);
    const int area = cv::floodFill(
        depth_copy, region, seed, cv::Scalar(), nullptr, cv::Scalar(range), cv::Scalar(range),
        4 | cv::FLOODFILL_FIXED_RANGE | cv::FLOODFILL_MASK_ONLY | (255 << 8));
    const cv::Mat inside = region(cv::Rect(1, 1, depth.cols, depth.rows));
    visited.setTo(255, inside);
    if (area > max_area) continue;
    int seeds_inside = 0;
    for (const cv::Point& other : seeds) seeds_inside += inside.at<std::uint8_t>(other) != 0;
    if (seeds_inside >= options_.min_seeds_per_object) dynamic.setTo(255, inside);
  }
  return dynamic;
}

}  // namespace segslam::segmentation
