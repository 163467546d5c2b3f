#include "segslam/loop/loop_verifier.h"

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <map>
#include <random>

#include "segslam/feature/descriptor_distance.h"
#include "segslam/feature/descriptor_matcher.h"
#include "segslam/optim/pose_optimizer.h"

namespace segslam::loop {

namespace {

struct Correspondence {
  std::size_t keypoint;
  std::size_t point;  // index into the candidate points
};

optim::RgbdObservation observationOf(const LoopQuery& query, std::size_t i) {
  const auto& kp = query.keypoints_un[i];
  return {{kp.pt.x, kp.pt.y}, query.right_u[i], query.camera->levels.inverseSigma2()[kp.octave]};
}

bool reprojects(const LoopQuery& query, std::size_t i, const geometry::Pose& T_cw,
                const Eigen::Vector3d& point_w) {
  const Eigen::Vector3d p = T_cw * point_w;
  if (p.z() <= 0.0) return false;
  const auto& s = query.camera->stereo;
  const optim::RgbdObservation observation = observationOf(query, i);
  const double u = s.fx * p.x() / p.z() + s.cx;
  const double v = s.fy * p.y() / p.z() + s.cy;
  const double du = observation.pixel.x() - u;
  const double dv = observation.pixel.y() - v;
  double chi2 = du * du + dv * dv;
  if (observation.hasDepth()) {
    const double dr = observation.right_u - (u - s.bf / p.z());
    chi2 += dr * dr;
  }
  return chi2 * observation.information < optim::chi2Threshold(observation);
}

std::vector<Correspondence> matchWithDepth(const LoopQuery& query,
                                           const std::vector<LoopMapPoint>& points,
                                           const LoopVerifierOptions& options) {
  std::vector<std::size_t> with_depth;
  for (std::size_t i = 0; i < query.depth.size(); ++i) {
    if (query.depth[i] > 0.0f) with_depth.push_back(i);
  }
  if (with_depth.empty() || points.empty()) return {};
  cv::Mat query_descriptors(static_cast<int>(with_depth.size()), feature::kDescriptorBytes, CV_8U);
  for (std::size_t k = 0; k < with_depth.size(); ++k) {
    query.descriptors.row(static_cast<int>(with_depth[k]))
        .copyTo(query_descriptors.row(static_cast<int>(k)));
  }
  cv::Mat point_descriptors(static_cast<int>(points.size()), feature::kDescriptorBytes, CV_8U);
  for (std::size_t p = 0; p < points.size(); ++p) {
    points[p].descriptor.copyTo(point_descriptors.row(static_cast<int>(p)));
  }
  std::vector<Correspondence> matches;
  for (const cv::DMatch& m : feature::matchDescriptors(query_descriptors, point_descriptors,
                                                       {options.max_distance, options.ratio})) {
    matches.push_back(
        {with_depth[static_cast<std::size_t>(m.queryIdx)], static_cast<std::size_t>(m.trainIdx)});
  }
  return matches;
}

// Rigid transform mapping the world points onto the query's camera points (T_cw).
geometry::Pose alignRigidly(const LoopQuery& query, const std::vector<LoopMapPoint>& points,
                            const std::vector<Correspondence>& subset) {
  Eigen::Matrix3Xd world(3, subset.size());
  Eigen::Matrix3Xd camera(3, subset.size());
  for (std::size_t k = 0; k < subset.size(); ++k) {
    const auto& kp = query.keypoints_un[subset[k].keypoint];
    world.col(static_cast<Eigen::Index>(k)) = points[subset[k].point].position;
    camera.col(static_cast<Eigen::Index>(k)) =
        query.camera->camera.backProject(kp.pt.x, kp.pt.y, query.depth[subset[k].keypoint]);
  }
  geometry::Pose T_cw;
  T_cw.matrix() = Eigen::umeyama(world, camera, /*with_scaling=*/false);
  return geometry::orthonormalised(T_cw);
}

std::vector<Correspondence> inliersOf(const LoopQuery& query,
                                      const std::vector<LoopMapPoint>& points,
                                      const std::vector<Correspondence>& matches,
                                      const geometry::Pose& T_cw) {
  std::vector<Correspondence> inliers;
  for (const Correspondence& c : matches) {
    if (reprojects(query, c.keypoint, T_cw, points[c.point].position)) inliers.push_back(c);
  }
  return inliers;
}

bool wellSpread(const LoopQuery& query, const std::vector<Correspondence>& sample) {
  std::array<Eigen::Vector2d, 3> pixels;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& pt = query.keypoints_un[sample[k].keypoint].pt;
    pixels[k] = {pt.x, pt.y};
  }
  const Eigen::Vector2d a = pixels[1] - pixels[0];
  const Eigen::Vector2d b = pixels[2] - pixels[0];
  return std::abs(a.x() * b.y() - a.y() * b.x()) > 100.0;  // twice the triangle's area, px^2
}

std::vector<Correspondence> ransac(const LoopQuery& query, const std::vector<LoopMapPoint>& points,
                                   const std::vector<Correspondence>& matches,
                                   const LoopVerifierOptions& options) {
  std::vector<Correspondence> best;
  if (matches.size() < 3) return best;
  std::mt19937 rng(options.seed);
  std::uniform_int_distribution<std::size_t> pick(0, matches.size() - 1);
  for (int iteration = 0; iteration < options.ransac_iterations; ++iteration) {
    const std::size_t a = pick(rng);
    const std::size_t b = pick(rng);
    const std::size_t c = pick(rng);
    if (a == b || b == c || a == c) continue;
    const std::vector<Correspondence> sample = {matches[a], matches[b], matches[c]};
    if (!wellSpread(query, sample)) continue;
    auto inliers = inliersOf(query, points, matches, alignRigidly(query, points, sample));
    if (inliers.size() > best.size()) best = std::move(inliers);
  }
  return best;
}

struct RefinedPose {
  geometry::Pose T_cw;
  std::vector<Correspondence> inliers;
};

RefinedPose refine(const LoopQuery& query, const std::vector<LoopMapPoint>& points,
                   const std::vector<Correspondence>& correspondences,
                   const geometry::Pose& initial_T_cw) {
  std::vector<optim::PoseObservation> observations;
  for (const Correspondence& c : correspondences) {
    observations.push_back({points[c.point].position, observationOf(query, c.keypoint)});
  }
  const auto result = optim::optimizePose(query.camera->stereo, initial_T_cw, observations);
  RefinedPose refined{result.T_cw, {}};
  for (std::size_t k = 0; k < correspondences.size(); ++k) {
    if (result.inlier[k]) refined.inliers.push_back(correspondences[k]);
  }
  return refined;
}

// For every local map point that projects into the query, the best-matching keypoint near its
// projection whose reprojection passes the chi2 test; each keypoint keeps its best point.
std::vector<Correspondence> searchByProjection(const LoopQuery& query,
                                               const std::vector<LoopMapPoint>& points,
                                               const geometry::Pose& T_cw,
                                               const LoopVerifierOptions& options) {
  const auto& s = query.camera->stereo;
  std::map<std::size_t, std::pair<int, std::size_t>> best_for_keypoint;  // distance, point
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Eigen::Vector3d p_c = T_cw * points[p].position;
    if (p_c.z() <= 0.0) continue;
    const double u = s.fx * p_c.x() / p_c.z() + s.cx;
    const double v = s.fy * p_c.y() / p_c.z() + s.cy;
    if (!query.grid.contains(u, v)) continue;
    int best_distance = options.max_distance + 1;
    std::size_t best = SIZE_MAX;
    for (std::size_t i :
         query.grid.featuresInArea(query.keypoints_un, u, v, options.search_radius_px)) {
      if (!reprojects(query, i, T_cw, points[p].position)) continue;
      const int d = feature::descriptorDistance(points[p].descriptor.ptr<std::uint8_t>(),
                                                query.descriptors.ptr<std::uint8_t>(i));
      if (d < best_distance) {
        best_distance = d;
        best = i;
      }
    }
    if (best == SIZE_MAX) continue;
    auto [it, inserted] = best_for_keypoint.try_emplace(best, best_distance, p);
    if (!inserted && best_distance < it->second.first) it->second = {best_distance, p};
  }
  std::vector<Correspondence> matches;
  for (const auto& [keypoint, entry] : best_for_keypoint)
    matches.push_back({keypoint, entry.second});
  return matches;
}

}  // namespace

LoopQuery LoopQuery::of(const map::KeyFrame& keyframe) {
  return {keyframe.camera,  keyframe.keypoints_un,        keyframe.depth,
          keyframe.right_u, keyframe.descriptors.clone(), keyframe.grid};
}

LoopVerification verifyLoop(const LoopQuery& query,
                            const std::vector<LoopMapPoint>& candidate_points,
                            const std::vector<LoopMapPoint>& local_map,
                            const LoopVerifierOptions& options) {
  LoopVerification verification;
  const auto matches = matchWithDepth(query, candidate_points, options);
  verification.matches = static_cast<int>(matches.size());
  const auto consensus = ransac(query, candidate_points, matches, options);
  verification.ransac_inliers = static_cast<int>(consensus.size());
  if (verification.ransac_inliers < options.min_ransac_inliers) return verification;

  const RefinedPose first =
      refine(query, candidate_points, consensus, alignRigidly(query, candidate_points, consensus));
  if (static_cast<int>(first.inliers.size()) < options.min_ransac_inliers) return verification;
  const auto projected = searchByProjection(query, local_map, first.T_cw, options);
  const RefinedPose final_pose = refine(query, local_map, projected, first.T_cw);
  verification.T_cw = final_pose.T_cw;
  verification.inliers = static_cast<int>(final_pose.inliers.size());
  verification.accepted = verification.inliers >= options.min_inliers;
  for (const Correspondence& c : final_pose.inliers) {
    verification.matched_points.emplace_back(c.keypoint, local_map[c.point].point);
  }
  return verification;
}

}  // namespace segslam::loop
