#include "segslam/system/map_evaluation.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <opencv2/core.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "segslam/dense/keyframe_cloud.h"
#include "segslam/dense/nearest_neighbours.h"
#include "segslam/dense/ply_io.h"
#include "segslam/eval/ate.h"
#include "segslam/eval/statistics.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/system/occupancy_output.h"
#include "segslam/util/error.h"

namespace segslam::system {

namespace {

// Ground-truth pose at a frame: interpolated between the poses around it (TUM ground truth is
// sampled independently of the images), when they are at most 0.1 s apart.
std::optional<geometry::Pose> groundTruthPose(const core::Trajectory& trajectory, double t) {
  const auto& poses = trajectory.poses();
  const auto after = std::lower_bound(
      poses.begin(), poses.end(), t,
      [](const core::StampedPose& pose, double time) { return pose.timestamp < time; });
  if (after != poses.end() && after->timestamp - t < 1e-6) return after->T_wc;
  if (after == poses.begin() || after == poses.end()) return std::nullopt;
  const auto before = std::prev(after);
  const double gap = after->timestamp - before->timestamp;
  if (gap > 0.1) return std::nullopt;
  const double s = (t - before->timestamp) / gap;
  const Eigen::Quaterniond q0(before->T_wc.linear());
  const Eigen::Quaterniond q1(after->T_wc.linear());
  geometry::Pose pose = geometry::Pose::Identity();
  pose.linear() = q0.slerp(s, q1).toRotationMatrix();
  pose.translation() = (1.0 - s) * before->T_wc.translation() + s * after->T_wc.translation();
  return pose;
}

// Pixel of a camera-frame point through the full lens model (the masks and depth images are the
// distorted images).
Eigen::Vector2d projectDistorted(const core::Camera& camera, const Eigen::Vector3d& p_c) {
  const double x = p_c.x() / p_c.z();
  const double y = p_c.y() / p_c.z();
  const auto& [k1, k2, p1, p2, k3] = camera.distortion;
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x);
  const double yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y;
  return {camera.fx * xd + camera.cx, camera.fy * yd + camera.cy};
}

// Marks the points that lie on a moving object in this frame: they project into its mask, where
// the ground-truth depth agrees with theirs within `tolerance`. A static point that the object
// merely hides is farther than the depth there and stays unmarked.
void markOnDynamic(const std::vector<Eigen::Vector3f>& points, const io::RgbdFrame& frame,
                   const geometry::Pose& T_wc, const core::Camera& camera, double tolerance,
                   std::vector<std::uint8_t>& on_dynamic) {
  const Eigen::Isometry3d T_cw = T_wc.inverse();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 8192),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        if (on_dynamic[i]) continue;
                        const Eigen::Vector3d p_c = T_cw * points[i].cast<double>();
                        if (p_c.z() <= 0.0) continue;
                        const Eigen::Vector2d uv = projectDistorted(camera, p_c);
                        const int u = static_cast<int>(std::lround(uv.x()));
                        const int v = static_cast<int>(std::lround(uv.y()));
                        if (u < 0 || v < 0 || u >= frame.mask.cols || v >= frame.mask.rows) {
                          continue;
                        }
                        if (frame.mask.at<std::uint8_t>(v, u) == 0) continue;
                        const float depth = frame.depth.at<float>(v, u);
                        if (depth > 0.0f && std::abs(depth - p_c.z()) <= tolerance) {
                          on_dynamic[i] = 1;
                        }
                      }
                    });
}

struct GroundTruthComparison {
  std::vector<Eigen::Vector3f> static_surface;
  std::vector<Eigen::Vector3f> dynamic_surface;  // the moving objects', 2 cm grid
  std::size_t on_dynamic_points = 0;
};

// Goes through the frames with their ground-truth poses: the static pixels of every stride-th
// frame back-projected make the true static surface (1 cm grid); every frame with a moving object
// marks the map points on it.
GroundTruthComparison compareWithFrames(const io::TumDataset& dataset,
                                        const std::vector<Eigen::Vector3f>& map_points,
                                        const MapEvaluationOptions& options) {
  dense::KeyFrameCloudOptions cloud_options;
  cloud_options.voxel_size = 0.01;
  cloud_options.max_depth = options.max_depth;
  cloud_options.mask_dilation_px = 0;
  const dense::KeyFrameCloudMaker maker(dataset.camera(), cloud_options);
  dense::LabelledCloud static_surface;
  dense::LabelledCloud dynamic_surface;
  std::vector<std::uint8_t> on_dynamic(map_points.size(), 0);
  for (std::size_t i = 0; i < dataset.size(); ++i) {
    const auto T_wc = groundTruthPose(*dataset.groundTruth(), dataset.frames()[i].timestamp);
    if (!T_wc) continue;
    const io::RgbdFrame frame = dataset.loadFrame(i);
    if (i % std::max<std::size_t>(options.frame_stride, 1) == 0) {
      const auto cloud = maker.make({frame.rgb, frame.depth, frame.mask, {}, {}});
      static_surface.append(dense::transformed(cloud.static_points, *T_wc));
      // Keeps memory to the grid's size while frames accumulate.
      if (static_surface.size() > 4'000'000) {
        static_surface = dense::voxelDownsample(static_surface, 0.01);
      }
    }
    if (!frame.mask.empty() && cv::countNonZero(frame.mask) > 0) {
      markOnDynamic(map_points, frame, *T_wc, dataset.camera(), options.on_dynamic_distance,
                    on_dynamic);
      const auto cloud = maker.make({frame.rgb, frame.depth, frame.mask, {}, {}});
      dynamic_surface.append(
          dense::voxelDownsample(dense::transformed(cloud.dynamic_points, *T_wc), 0.02));
    }
  }
  GroundTruthComparison comparison;
  comparison.static_surface = dense::voxelDownsample(static_surface, 0.01).points;
  comparison.dynamic_surface = dense::voxelDownsample(dynamic_surface, 0.02).points;
  comparison.on_dynamic_points =
      static_cast<std::size_t>(std::count(on_dynamic.begin(), on_dynamic.end(), 1));
  return comparison;
}

struct PersonTrack {
  std::vector<Eigen::Vector3d> floor_points;
};

Eigen::Vector3d worldUp(const std::filesystem::path& meta_file) {
  std::ifstream in(meta_file);
  if (!in) util::failAt(meta_file, "cannot open (needed for the world's up direction)");
  nlohmann::json meta;
  try {
    meta = nlohmann::json::parse(in);
    const auto up = meta.at("scene").at("world_up");
    const Eigen::Vector3d v(up.at(0).get<double>(), up.at(1).get<double>(), up.at(2).get<double>());
    if (!(v.norm() > 0.5)) util::failAt(meta_file, "scene.world_up is not a direction");
    return v.normalized();
  } catch (const nlohmann::json::exception& e) {
    util::failAt(meta_file, fmt::format("no scene.world_up: {}", e.what()));
  }
}

// persons_gt.txt: `timestamp person_id cutout x y z ...`, the floor point under the person.
std::map<int, PersonTrack> readPersonTracks(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) util::failAt(file, "cannot open");
  std::map<int, PersonTrack> tracks;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double timestamp = 0.0;
    int person = 0;
    std::string cutout;
    Eigen::Vector3d floor_point;
    fields >> timestamp >> person >> cutout >> floor_point.x() >> floor_point.y() >>
        floor_point.z();
    if (!fields || !floor_point.allFinite()) {
      util::failAt(file, line_number, "expected 'timestamp person_id cutout x y z ...'");
    }
    tracks[person].floor_points.push_back(floor_point);
  }
  return tracks;
}

// Horizontal distance of p to the segment a-b, with heights removed along `up`.
double horizontalDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& up) {
  const auto flat = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(v - v.dot(up) * up); };
  const Eigen::Vector3d fp = flat(p);
  const Eigen::Vector3d fa = flat(a);
  const Eigen::Vector3d ab = flat(b) - fa;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((fp - fa).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (fp - (fa + s * ab)).norm();
}

bool nearPersonPath(const Eigen::Vector3d& p, const std::map<int, PersonTrack>& tracks,
                    const Eigen::Vector3d& up, const MapEvaluationOptions& options) {
  for (const auto& [id, track] : tracks) {
    const auto& floor = track.floor_points;
    for (std::size_t i = 0; i < floor.size(); ++i) {
      const Eigen::Vector3d& a = floor[i];
      const Eigen::Vector3d& b = floor[std::min(i + 1, floor.size() - 1)];
      const double height = (p - a).dot(up);
      if (height < 0.0 || height > options.person_height) continue;
      if (horizontalDistance(p, a, b, up) <= options.person_radius) return true;
    }
  }
  return false;
}

// The rigid motion from the run's world into the ground truth's over the matched poses: the
// rotation nearest to the sum of the per-pose rotations R_gt R_est^T (chordal mean), then the
// mean translation. Unlike aligning positions only, it stays well defined when the camera barely
// moves, and a tracked run's poses fix it.
eval::Alignment poseAlignment(const core::Trajectory& ground_truth,
                              const core::Trajectory& estimate, const eval::AteResult& ate) {
  Eigen::Matrix3d rotation_sum = Eigen::Matrix3d::Zero();
  for (const auto& pair : ate.pairs) {
    rotation_sum += ground_truth[pair.gt_index].T_wc.linear() *
                    estimate[pair.est_index].T_wc.linear().transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(rotation_sum,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) correction(2, 2) = -1.0;
  eval::Alignment alignment;
  alignment.rotation = svd.matrixU() * correction * svd.matrixV().transpose();
  Eigen::Vector3d translation_sum = Eigen::Vector3d::Zero();
  for (const auto& pair : ate.pairs) {
    translation_sum += ground_truth[pair.gt_index].T_wc.translation() -
                       alignment.rotation * estimate[pair.est_index].T_wc.translation();
  }
  alignment.translation = translation_sum / static_cast<double>(ate.pairs.size());
  return alignment;
}

// The reference run's occupancy map, aligned onto the ground truth as a run's map is.
AlignedOccupancy referenceOccupancy(const io::TumDataset& dataset,
                                    const std::filesystem::path& run_dir) {
  const auto estimate = io::readTumTrajectory(run_dir / "CameraTrajectory.txt");
  const auto ate = eval::evaluateAte(*dataset.groundTruth(), estimate);
  return {run_dir / "map" / occupancy::kOccupancyFile,
          poseAlignment(*dataset.groundTruth(), estimate, ate)};
}

}  // namespace

MapEvaluation evaluateMap(const io::TumDataset& dataset, const std::filesystem::path& run_dir,
                          const MapEvaluationOptions& options) {
  if (!dataset.groundTruth()) {
    util::failAt(dataset.folder() / "groundtruth.txt", "needed to evaluate a map");
  }
  MapEvaluation evaluation;
  evaluation.map_file = run_dir / "map" / "static.ply";
  const auto estimate = io::readTumTrajectory(run_dir / "CameraTrajectory.txt");
  const auto ate = eval::evaluateAte(*dataset.groundTruth(), estimate);
  evaluation.trajectory_ate_rmse = ate.statistics.rmse;
  std::vector<Eigen::Vector3f> map_points = dense::readPly(evaluation.map_file).points;
  const eval::Alignment alignment = poseAlignment(*dataset.groundTruth(), estimate, ate);
  for (auto& p : map_points) p = alignment.apply(p.cast<double>()).cast<float>();
  evaluation.static_points = map_points.size();

  std::optional<GroundTruthComparison> truth_surfaces;
  if (dataset.hasMasks()) {
    truth_surfaces = compareWithFrames(dataset, map_points, options);
    const auto& truth = *truth_surfaces;
    evaluation.on_dynamic_points = truth.on_dynamic_points;
    evaluation.on_dynamic_share = eval::share(*evaluation.on_dynamic_points, map_points.size());
    const dense::NearestNeighbours map_index(map_points);
    evaluation.surface_points = truth.static_surface.size();
    evaluation.completeness =
        eval::share(map_index.countWithin(truth.static_surface, options.surface_distance),
                    truth.static_surface.size());
    const dense::NearestNeighbours surface_index(truth.static_surface);
    evaluation.accuracy = eval::share(
        surface_index.countWithin(map_points, options.surface_distance), map_points.size());
  }

  const auto persons_file = dataset.folder() / "persons_gt.txt";
  if (std::filesystem::exists(persons_file)) {
    const auto tracks = readPersonTracks(persons_file);
    const Eigen::Vector3d up = worldUp(dataset.folder() / "meta.json");
    std::size_t near = 0;
    for (const auto& p : map_points) {
      if (nearPersonPath(p.cast<double>(), tracks, up, options)) ++near;
    }
    evaluation.near_person_path_points = near;
    evaluation.near_person_path_share = eval::share(near, map_points.size());
  }

  const auto occupancy_file = run_dir / "map" / occupancy::kOccupancyFile;
  if (std::filesystem::exists(occupancy_file)) {
    std::optional<AlignedOccupancy> reference;
    if (options.occupancy_reference_run) {
      reference = referenceOccupancy(dataset, *options.occupancy_reference_run);
    }
    evaluation.occupancy =
        evaluateOccupancy({occupancy_file, alignment},
                          truth_surfaces ? &truth_surfaces->dynamic_surface : nullptr, reference);
  }
  return evaluation;
}

nlohmann::json toJson(const MapEvaluation& evaluation, const MapEvaluationOptions& options) {
  nlohmann::json json = {{"map", evaluation.map_file.string()},
                         {"static_points", evaluation.static_points},
                         {"trajectory_ate_rmse_m", evaluation.trajectory_ate_rmse}};
  if (evaluation.on_dynamic_share) {
    json["on_dynamic_points"] = *evaluation.on_dynamic_points;
    json["on_dynamic_share"] = *evaluation.on_dynamic_share;
    json["on_dynamic_distance_m"] = options.on_dynamic_distance;
    json["completeness"] = *evaluation.completeness;
    json["accuracy"] = *evaluation.accuracy;
    json["surface_distance_m"] = options.surface_distance;
    json["surface_points"] = evaluation.surface_points;
  }
  if (evaluation.near_person_path_share) {
    json["near_person_path_points"] = *evaluation.near_person_path_points;
    json["near_person_path_share"] = *evaluation.near_person_path_share;
    json["person_radius_m"] = options.person_radius;
    json["person_height_m"] = options.person_height;
  }
  if (evaluation.occupancy) json["occupancy"] = toJson(*evaluation.occupancy);
  return json;
}

}  // namespace segslam::system
