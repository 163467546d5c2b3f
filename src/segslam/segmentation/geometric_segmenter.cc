#include "segslam/segmentation/geometric_segmenter.h"

#include <algorithm>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <optional>
#include <vector>

#include "segslam/core/undistortion.h"
#include "segslam/feature/static_mask.h"
#include "segslam/segmentation/strongest_corners.h"
#include "segslam/util/error.h"

namespace segslam::segmentation {

namespace {

constexpr int kMinStaticCorrespondences = 12;

float depthAt(const cv::Mat& depth, const cv::Point2f& p) {
  const int x = cvRound(p.x);
  const int y = cvRound(p.y);
  if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) return 0.0f;
  return depth.at<float>(y, x);
}

// Lucas-Kanade tracks that do not come back to where they started (occlusion, blur, repeated
// texture) would look like motion; they are dropped.
constexpr float kMaxForwardBackwardPx = 1.0f;

// Corners of `current` and where they were in `previous` (raw pixels), tracked ones only.
void trackCorners(const DepthFrame& previous, const DepthFrame& current, int max_corners,
                  std::vector<cv::Point2f>& previous_corners,
                  std::vector<cv::Point2f>& current_corners) {
  const std::vector<cv::Point2f> corners = strongestCorners(current.gray, max_corners, 0.01, 10.0);
  if (corners.empty()) return;
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
    current_corners.push_back(corners[i]);
    previous_corners.push_back(back[i]);
  }
}

// A camera motion found by PnP RANSAC and the correspondences it explains.
struct RigidMotion {
  cv::Mat rvec;
  cv::Mat tvec;
  std::vector<int> inliers;
};

std::optional<RigidMotion> solveRigidMotion(const std::vector<cv::Point3f>& points,
                                            const std::vector<cv::Point2f>& pixels,
                                            const cv::Mat& k, float reprojection_px) {
  if (points.size() < static_cast<std::size_t>(kMinStaticCorrespondences)) return std::nullopt;
  RigidMotion motion;
  if (!cv::solvePnPRansac(points, pixels, k, cv::noArray(), motion.rvec, motion.tvec, false, 100,
                          reprojection_px, 0.99, motion.inliers)) {
    return std::nullopt;
  }
  return motion;
}

float medianDepth(const std::vector<cv::Point3f>& points, const std::vector<int>& chosen) {
  std::vector<float> depths;
  for (int i : chosen) depths.push_back(points[static_cast<std::size_t>(i)].z);
  if (depths.empty()) return 0.0f;
  const auto middle = depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2);
  std::nth_element(depths.begin(), middle, depths.end());
  return *middle;
}

// A person close to the camera can carry as many tracked corners as the whole background, and
// RANSAC then takes the person's motion for the camera's. The corners the first motion leaves
// out are tried as a second motion; when it has comparable support and its points lie farther
// away, it is the camera's: what moves in front of the camera is nearer than the room behind it.
RigidMotion backgroundMotion(RigidMotion first, const std::vector<cv::Point3f>& points,
                             const std::vector<cv::Point2f>& pixels, const cv::Mat& k,
                             float reprojection_px) {
  std::vector<bool> explained(points.size(), false);
  for (int i : first.inliers) explained[static_cast<std::size_t>(i)] = true;
  std::vector<cv::Point3f> other_points;
  std::vector<cv::Point2f> other_pixels;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (explained[i]) continue;
    other_points.push_back(points[i]);
    other_pixels.push_back(pixels[i]);
  }
  auto second = solveRigidMotion(other_points, other_pixels, k, reprojection_px);
  if (!second || 2 * second->inliers.size() < first.inliers.size() ||
      second->inliers.size() < static_cast<std::size_t>(kMinStaticCorrespondences)) {
    return first;
  }
  if (medianDepth(other_points, second->inliers) <= medianDepth(points, first.inliers)) {
    return first;
  }
  return *second;
}

}  // namespace

CameraMotionModel cameraMotionModelFromName(const std::string& name) {
  if (name == "rigid") return CameraMotionModel::kRigid;
  if (name == "homography") return CameraMotionModel::kHomography;
  throw util::Error("unknown camera motion model '" + name + "' (known: rigid, homography)");
}

// Tracked corners in both frames, raw and undistorted, and whether each is already known to move.
struct GeometricSegmenter::Correspondences {
  std::vector<cv::Point2f> previous_raw;
  std::vector<cv::Point2f> current_raw;
  std::vector<cv::Point2f> previous_un;
  std::vector<cv::Point2f> current_un;
  std::vector<bool> known_dynamic;
  cv::Mat previous_depth;
  cv::Mat current_depth;
};

GeometricSegmenter::GeometricSegmenter(const core::Camera& camera, GeometricOptions options)
    : camera_(camera), options_(options) {}

cv::Mat GeometricSegmenter::segment(const DepthFrame& previous, const DepthFrame& current,
                                    const cv::Mat& known_dynamic) const {
  Correspondences tracks;
  trackCorners(previous, current, options_.max_corners, tracks.previous_raw, tracks.current_raw);
  tracks.previous_un = core::undistortPixels(tracks.previous_raw, camera_);
  tracks.current_un = core::undistortPixels(tracks.current_raw, camera_);
  for (std::size_t i = 0; i < tracks.current_raw.size(); ++i) {
    tracks.known_dynamic.push_back(feature::isDynamicAt(known_dynamic, tracks.current_raw[i]) ||
                                   feature::isDynamicAt(previous.moving, tracks.previous_raw[i]));
  }
  tracks.previous_depth = previous.depth;
  tracks.current_depth = current.depth;
  const auto evidence = options_.motion_model == CameraMotionModel::kRigid
                            ? rigidMotionEvidence(tracks)
                            : homographyEvidence(tracks);
  if (!evidence) return {};
  cv::Mat dynamic = growObjects(current.depth, *evidence);
  if (cv::countNonZero(dynamic) >
      options_.max_moving_share * static_cast<double>(dynamic.total())) {
    return {};
  }
  return dynamic;
}

std::optional<GeometricSegmenter::MotionEvidence> GeometricSegmenter::rigidMotionEvidence(
    const Correspondences& tracks) const {
  // 3D points of the previous frame with their current pixels; static candidates for the pose.
  std::vector<cv::Point3f> points;
  std::vector<cv::Point2f> pixels;
  std::vector<std::size_t> track_of;
  std::vector<cv::Point3f> static_points;
  std::vector<cv::Point2f> static_pixels;
  for (std::size_t i = 0; i < tracks.current_raw.size(); ++i) {
    const float z = depthAt(tracks.previous_depth, tracks.previous_raw[i]);
    if (z <= 0.0f) continue;
    const Eigen::Vector3d p =
        camera_.backProject(tracks.previous_un[i].x, tracks.previous_un[i].y, z);
    points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                        static_cast<float>(p.z()));
    pixels.push_back(tracks.current_un[i]);
    track_of.push_back(i);
    if (!tracks.known_dynamic[i]) {
      static_points.push_back(points.back());
      static_pixels.push_back(tracks.current_un[i]);
    }
  }
  const cv::Mat k = core::cameraMatrix(camera_);
  const auto threshold = static_cast<float>(options_.reprojection_px) * 0.7f;
  const auto first = solveRigidMotion(static_points, static_pixels, k, threshold);
  if (!first) return std::nullopt;
  const RigidMotion camera_motion =
      backgroundMotion(*first, static_points, static_pixels, k, threshold);
  const cv::Mat& rvec = camera_motion.rvec;
  const cv::Mat& tvec = camera_motion.tvec;

  // Seeds: corners whose image position or depth the camera motion does not explain.
  std::vector<cv::Point2f> predicted;
  cv::projectPoints(points, rvec, tvec, k, cv::noArray(), predicted);
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  MotionEvidence evidence;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const cv::Mat p = rotation * cv::Mat(cv::Vec3d(points[j].x, points[j].y, points[j].z)) + tvec;
    const double z_predicted = p.at<double>(2);
    const cv::Point2f& corner = tracks.current_raw[track_of[j]];
    const float z_observed = depthAt(tracks.current_depth, corner);
    const bool image_motion = cv::norm(predicted[j] - pixels[j]) > options_.reprojection_px;
    const bool depth_motion = z_observed > 0.0f && std::abs(z_predicted - z_observed) >
                                                       options_.depth_tolerance * z_observed;
    (image_motion || depth_motion ? evidence.moving : evidence.explained).push_back(corner);
  }
  return evidence;
}

std::optional<GeometricSegmenter::MotionEvidence> GeometricSegmenter::homographyEvidence(
    const Correspondences& tracks) const {
  std::vector<cv::Point2f> static_previous;
  std::vector<cv::Point2f> static_current;
  for (std::size_t i = 0; i < tracks.current_un.size(); ++i) {
    if (tracks.known_dynamic[i]) continue;
    static_previous.push_back(tracks.previous_un[i]);
    static_current.push_back(tracks.current_un[i]);
  }
  if (static_previous.size() < static_cast<std::size_t>(kMinStaticCorrespondences)) {
    return std::nullopt;
  }
  const cv::Mat homography =
      cv::findHomography(static_previous, static_current, cv::RANSAC, options_.reprojection_px);
  if (homography.empty()) return std::nullopt;
  std::vector<cv::Point2f> predicted;
  cv::perspectiveTransform(tracks.previous_un, predicted, homography);
  MotionEvidence evidence;
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    const bool moving = cv::norm(predicted[i] - tracks.current_un[i]) > options_.reprojection_px;
    (moving ? evidence.moving : evidence.explained).push_back(tracks.current_raw[i]);
  }
  return evidence;
}

namespace {

int countInside(const cv::Mat& region, const std::vector<cv::Point>& corners) {
  int inside = 0;
  for (const cv::Point& corner : corners) inside += region.at<std::uint8_t>(corner) != 0;
  return inside;
}

}  // namespace

cv::Mat GeometricSegmenter::growObjects(const cv::Mat& depth,
                                        const MotionEvidence& evidence) const {
  cv::Mat dynamic = cv::Mat::zeros(depth.size(), CV_8UC1);
  cv::Mat visited = cv::Mat::zeros(depth.size(), CV_8UC1);
  const double max_area = options_.max_object_share * static_cast<double>(depth.total());
  cv::Mat depth_copy = depth.clone();
  for (const cv::Point& seed : evidence.moving) {
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
    const int seeds_inside = countInside(inside, evidence.moving);
    const int explained_inside = countInside(inside, evidence.explained);
    const bool enough_seeds = seeds_inside >= options_.min_seeds_per_object;
    const bool mostly_moving =
        seeds_inside >= options_.min_seed_share * (seeds_inside + explained_inside);
    if (enough_seeds && mostly_moving) dynamic.setTo(255, inside);
  }
  return dynamic;
}

}  // namespace segslam::segmentation
