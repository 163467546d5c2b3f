#include "segslam/system/occupancy_evaluation.h"

#include <octomap/OcTree.h>

#include <cmath>

#include "segslam/dense/nearest_neighbours.h"
#include "segslam/eval/statistics.h"
#include "segslam/occupancy/occupancy_map.h"

namespace segslam::system {

namespace {

// Whether a voxel of `tree` at `p` or one of its 26 neighbours is occupied.
bool occupiedWithinOneVoxel(const octomap::OcTree& tree, const Eigen::Vector3d& p) {
  const double step = tree.getResolution();
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      for (int k = -1; k <= 1; ++k) {
        if (occupancy::stateAt(tree, p + step * Eigen::Vector3d(i, j, k)) ==
            occupancy::VoxelState::kOccupied) {
          return true;
        }
      }
    }
  }
  return false;
}

// Centres of the occupied voxels of `tree`, in the ground truth's frame.
std::vector<Eigen::Vector3d> occupiedInTruth(const octomap::OcTree& tree,
                                             const eval::Alignment& to_truth) {
  auto centres = occupancy::voxelCentres(tree, true);
  for (auto& centre : centres) centre = to_truth.apply(centre);
  return centres;
}

}  // namespace

OccupancyEvaluation evaluateOccupancy(const AlignedOccupancy& map,
                                      const std::vector<Eigen::Vector3f>* people,
                                      const std::optional<AlignedOccupancy>& reference) {
  const auto tree = occupancy::readOctree(map.file);
  OccupancyEvaluation evaluation;
  evaluation.file = map.file;
  evaluation.resolution_m = tree->getResolution();
  const auto occupied = occupiedInTruth(*tree, map.to_truth);
  evaluation.occupied_voxels = occupied.size();
  if (people != nullptr && !people->empty()) {
    // A voxel holds a point when the point is within half its diagonal of the centre.
    const dense::NearestNeighbours index(*people);
    std::vector<Eigen::Vector3f> centres;
    for (const auto& c : occupied) centres.push_back(c.cast<float>());
    const std::size_t on_people =
        index.countWithin(centres, 0.5 * std::sqrt(3.0) * evaluation.resolution_m);
    evaluation.on_people_voxels = on_people;
    evaluation.on_people_share = eval::share(on_people, occupied.size());
  }
  if (reference) {
    const auto reference_tree = occupancy::readOctree(reference->file);
    const eval::Alignment into_reference = reference->to_truth.inverse();
    std::size_t ghosts = 0;
    std::size_t ghosts_beyond_a_voxel = 0;
    for (const auto& c : occupied) {
      const Eigen::Vector3d in_reference = into_reference.apply(c);
      if (occupancy::stateAt(*reference_tree, in_reference) != occupancy::VoxelState::kFree) {
        continue;
      }
      ++ghosts;
      if (!occupiedWithinOneVoxel(*reference_tree, in_reference)) ++ghosts_beyond_a_voxel;
    }
    const eval::Alignment into_map = map.to_truth.inverse();
    const auto reference_occupied = occupiedInTruth(*reference_tree, reference->to_truth);
    std::size_t kept = 0;
    for (const auto& c : reference_occupied) {
      kept += occupiedWithinOneVoxel(*tree, into_map.apply(c)) ? 1 : 0;
    }
    evaluation.reference = reference->file;
    evaluation.ghost_voxels = ghosts;
    evaluation.ghost_share = eval::share(ghosts, occupied.size());
    evaluation.ghost_beyond_a_voxel_voxels = ghosts_beyond_a_voxel;
    evaluation.ghost_beyond_a_voxel_share = eval::share(ghosts_beyond_a_voxel, occupied.size());
    evaluation.reference_occupied_voxels = reference_occupied.size();
    evaluation.kept_share = eval::share(kept, reference_occupied.size());
  }
  return evaluation;
}

nlohmann::json toJson(const OccupancyEvaluation& e) {
  nlohmann::json json = {{"file", e.file.string()},
                         {"resolution_m", e.resolution_m},
                         {"occupied_voxels", e.occupied_voxels}};
  if (e.on_people_share) {
    json["on_people_voxels"] = *e.on_people_voxels;
    json["on_people_share"] = *e.on_people_share;
  }
  if (e.reference) {
    json["reference"] = e.reference->string();
    json["ghost_voxels"] = *e.ghost_voxels;
    json["ghost_share"] = *e.ghost_share;
    json["ghost_beyond_a_voxel_voxels"] = *e.ghost_beyond_a_voxel_voxels;
    json["ghost_beyond_a_voxel_share"] = *e.ghost_beyond_a_voxel_share;
    json["reference_occupied_voxels"] = *e.reference_occupied_voxels;
    json["kept_share"] = *e.kept_share;
  }
  return json;
}

}  // namespace segslam::system
