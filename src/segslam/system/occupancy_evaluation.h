#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "segslam/eval/alignment.h"

namespace segslam::system {

// An occupancy map and the rigid motion from its run's world into the ground truth's.
struct AlignedOccupancy {
  std::filesystem::path file;  // an OctoMap .bt
  eval::Alignment to_truth;
};

struct OccupancyEvaluation {
  std::filesystem::path file;
  double resolution_m = 0.0;
  std::size_t occupied_voxels = 0;
  // With the dataset's masks: occupied voxels holding a point of a moving object's true surface.
  std::optional<std::size_t> on_people_voxels;
  std::optional<double> on_people_share;
  // Against a reference, the map of the same frames without people: occupied voxels that it sees
  // free (ghosts), those of them with no occupied voxel of the reference within one voxel (not a
  // surface that the two runs place a voxel apart: two runs of the same static frames differ
  // in 8-12 % of their surface voxels at 5 cm), and its occupied voxels that this map holds
  // occupied within one voxel (kept).
  std::optional<std::filesystem::path> reference;
  std::optional<std::size_t> ghost_voxels;
  std::optional<double> ghost_share;
  std::optional<std::size_t> ghost_beyond_a_voxel_voxels;
  std::optional<double> ghost_beyond_a_voxel_share;
  std::optional<std::size_t> reference_occupied_voxels;
  std::optional<double> kept_share;
};

// Scores an occupancy map in the ground truth's frame. `people`: the moving objects' true
// surface there (empty: not scored). util::Error naming a file that cannot be read.
OccupancyEvaluation evaluateOccupancy(const AlignedOccupancy& map,
                                      const std::vector<Eigen::Vector3f>* people,
                                      const std::optional<AlignedOccupancy>& reference);

nlohmann::json toJson(const OccupancyEvaluation& evaluation);

}  // namespace segslam::system
