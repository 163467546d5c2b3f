#pragma once

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/map/frame.h"
#include "segslam/map/keyframe.h"
#include "segslam/map/map_point.h"

namespace segslam::loop {

// What verification needs of the query keyframe, copied under the map mutex so that the
// verification itself runs without it.
struct LoopQuery {
  std::shared_ptr<const map::FrameCamera> camera;
  std::vector<cv::KeyPoint> keypoints_un;
  std::vector<float> depth;    // metres, <= 0: none
  std::vector<float> right_u;  // < 0: none
  cv::Mat descriptors;
  map::KeypointGrid grid;

  static LoopQuery of(const map::KeyFrame& keyframe);
};

// A 3D feature of the loop candidate's neighbourhood (a keypoint with depth, in the world), with
// a snapshot of what matching reads.
struct LoopMapPoint {
  std::shared_ptr<map::MapPoint> point;  // the map point it belongs to; may be null
  Eigen::Vector3d position;
  cv::Mat descriptor;  // 1 x 32 CV_8U
};

struct LoopVerifierOptions {
  int max_distance = 50;  // Hamming bits for a descriptor match
  double ratio = 0.8;     // Lowe's ratio for the initial matches
  int ransac_iterations = 300;
  // Strict on purpose: on fr1/xyz with a walker and no masks a look-alike at 50 / 73 inliers was
  // 21 degrees off, while true loops on static scenes reach hundreds.
  int min_ransac_inliers = 60;
  int min_inliers = 120;          // after the projection search and pose refinement
  double search_radius_px = 8.0;  // projection search, at pyramid level 0
  std::uint32_t seed = 1;
};

struct LoopVerification {
  bool accepted = false;
  int matches = 0;         // initial descriptor matches with depth
  int ransac_inliers = 0;  // of the best rigid transform
  int inliers = 0;         // final, after projection search and refinement
  geometry::Pose T_cw = geometry::Pose::Identity();  // the query's pose in the candidate's map
  // Final inliers: query keypoint index -> the loop's map point (null where the loop's feature
  // has none).
  std::vector<std::pair<std::size_t, std::shared_ptr<map::MapPoint>>> matched_points;
};

// Geometric verification of a loop candidate. The query's keypoints with depth are matched (ratio
// test) to `candidate_points` (the candidate keyframe's points); a RANSAC over 3-point rigid
// alignments (Umeyama, no scale) of the query's back-projected keypoints onto the matched map
// points finds the query pose, an inlier being a match whose reprojection including the
// virtual-stereo coordinate passes the chi2 test. With at least `min_ransac_inliers` the pose is
// refined on its inliers, `local_map` (the candidate's neighbourhood) is projected into the query
// for more matches, and the pose is refined again on all of them; the loop is accepted with at
// least `min_inliers`. Deterministic for a given seed.
LoopVerification verifyLoop(const LoopQuery& query,
                            const std::vector<LoopMapPoint>& candidate_points,
                            const std::vector<LoopMapPoint>& local_map,
                            const LoopVerifierOptions& options = {});

}  // namespace segslam::loop
