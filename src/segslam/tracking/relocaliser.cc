#include "segslam/tracking/relocaliser.h"

#include <opencv2/calib3d.hpp>

#include "segslam/tracking/projection_search.h"

namespace segslam::tracking {

namespace {

constexpr int kMinMatches = 15;
constexpr int kMinInliers = 30;

struct PnpResult {
  geometry::Pose T_cw;
  std::vector<int> inliers;
};

std::optional<PnpResult> solvePnp(const map::Frame& frame,
                                  const std::vector<std::size_t>& matched) {
  std::vector<cv::Point3f> object_points;
  std::vector<cv::Point2f> image_points;
  for (std::size_t i : matched) {
    const Eigen::Vector3d& p = frame.map_points[i]->position;
    object_points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                               static_cast<float>(p.z()));
    image_points.push_back(frame.keypoints_un[i].pt);
  }
  const auto& s = frame.camera->stereo;
  const cv::Mat k = (cv::Mat_<double>(3, 3) << s.fx, 0, s.cx, 0, s.fy, s.cy, 0, 0, 1);
  cv::Mat rvec;
  cv::Mat tvec;
  std::vector<int> inliers;
  const bool ok = cv::solvePnPRansac(object_points, image_points, k, cv::noArray(), rvec, tvec,
                                     false, 300, 5.991, 0.99, inliers, cv::SOLVEPNP_EPNP);
  if (!ok || static_cast<int>(inliers.size()) < kMinInliers) return std::nullopt;
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  PnpResult result;
  result.T_cw = geometry::Pose::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) result.T_cw.linear()(r, c) = rotation.at<double>(r, c);
    result.T_cw.translation()(r) = tvec.at<double>(r);
  }
  result.inliers = std::move(inliers);
  return result;
}

}  // namespace

std::optional<geometry::Pose> relocaliseAgainstKeyFrames(
    map::Frame& frame, const std::vector<std::shared_ptr<map::KeyFrame>>& candidates,
    const RelocalisationCheck& accept) {
  for (const auto& keyframe : candidates) {
    std::fill(frame.map_points.begin(), frame.map_points.end(), nullptr);
    if (searchByDescriptors(frame, *keyframe, 0.75) < kMinMatches) continue;
    std::vector<std::size_t> matched;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (frame.map_points[i]) matched.push_back(i);
    }
    const auto pnp = solvePnp(frame, matched);
    if (!pnp) continue;
    std::vector<bool> keep(matched.size(), false);
    for (int k : pnp->inliers) keep[k] = true;
    for (std::size_t m = 0; m < matched.size(); ++m) {
      if (!keep[m]) frame.map_points[matched[m]].reset();
    }
    frame.reference_keyframe = keyframe;
    if (accept(pnp->T_cw)) return pnp->T_cw;
  }
  std::fill(frame.map_points.begin(), frame.map_points.end(), nullptr);
  return std::nullopt;
}

}  // namespace segslam::tracking
