#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "segslam/io/tum_dataset.h"
#include "segslam/system/occupancy_evaluation.h"

namespace segslam::system {

struct MapEvaluationOptions {
  // A static-map point lies on a moving object when, at some frame, it projects (ground-truth
  // pose) into the object's ground-truth mask and its depth is within this distance of the
  // ground-truth depth there (metres): it sits on the object's surface, not behind it.
  double on_dynamic_distance = 0.03;
  // Completeness and accuracy: distance between map and ground-truth static surface (metres).
  double surface_distance = 0.02;
  // The ground-truth surfaces are made of every n-th frame, with the map's depth range.
  std::size_t frame_stride = 3;
  double max_depth = 5.0;
  // persons_gt.txt: a static-map point is near the person's path when its horizontal distance
  // (perpendicular to meta.json's scene.world_up) to the polyline of the person's floor positions
  // is below person_radius and its height above that floor point is between 0 and
  // person_height: the vertical band the person sweeps.
  double person_radius = 0.3;
  double person_height = 2.0;
  // A run of the same frames without people, whose occupancy map the run's is scored against
  // (ghosts and kept, OccupancyEvaluation).
  std::optional<std::filesystem::path> occupancy_reference_run;
};

struct MapEvaluation {
  std::filesystem::path map_file;
  std::size_t static_points = 0;
  double trajectory_ate_rmse = 0.0;  // the run's ATE (SE(3) position alignment)
  // With mask.txt and ground truth:
  std::optional<std::size_t> on_dynamic_points;
  std::optional<double> on_dynamic_share;
  std::optional<double> completeness;  // share of ground-truth static surface near the map
  std::optional<double> accuracy;      // share of map points near ground-truth static surface
  std::size_t surface_points = 0;      // ground-truth static surface, 1 cm voxels
  // With persons_gt.txt:
  std::optional<std::size_t> near_person_path_points;
  std::optional<double> near_person_path_share;
  // When the run has map/occupancy.bt.
  std::optional<OccupancyEvaluation> occupancy;
};

// Scores <run>/map/static.ply (and map/occupancy.bt, when there is one) against the dataset's
// ground truth, in the ground-truth frame (the
// rigid motion that best maps the poses of the run's CameraTrajectory.txt onto those of
// groundtruth.txt, rotations included, so that short runs are aligned too). Throws util::Error
// when files are missing or malformed or the dataset lacks ground truth.
MapEvaluation evaluateMap(const io::TumDataset& dataset, const std::filesystem::path& run_dir,
                          const MapEvaluationOptions& options);

nlohmann::json toJson(const MapEvaluation& evaluation, const MapEvaluationOptions& options);

}  // namespace segslam::system
