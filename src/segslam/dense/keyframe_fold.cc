#include "segslam/dense/keyframe_fold.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "segslam/dense/seen_through.h"
#include "segslam/dense/voxel_key.h"

namespace segslam::dense {

namespace {

// A depth camera sees one surface a centimetre or two apart from two views: what lies within a
// cell of this many voxels, or the next, of a point the live keyframe holds is the same surface.
constexpr double kSameSurfaceVoxels = 2.0;

// Sorted, one allocation: a node-based set of ~40k cells per fold fragmented the map thread's
// heap with small blocks.
std::vector<std::uint64_t> occupiedCells(const KeyFrameCloud& cloud, double cell_size) {
  std::vector<std::uint64_t> occupied;
  occupied.reserve(cloud.static_points.size() + cloud.folded_points.size());
  for (const LabelledCloud* layer : {&cloud.static_points, &cloud.folded_points}) {
    for (const Eigen::Vector3f& p : layer->points) occupied.push_back(voxelKey(p, cell_size));
  }
  std::sort(occupied.begin(), occupied.end());
  occupied.erase(std::unique(occupied.begin(), occupied.end()), occupied.end());
  return occupied;
}

// packCell puts z in the lowest bits, so the three cells along z around a cell have consecutive
// keys: one search per (dx, dy).
bool nearOccupied(const Eigen::Vector3i& cell, const std::vector<std::uint64_t>& occupied) {
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      const std::uint64_t first = packCell(cell + Eigen::Vector3i(dx, dy, -1));
      const auto found = std::lower_bound(occupied.begin(), occupied.end(), first);
      if (found != occupied.end() && *found <= first + 2) return true;
    }
  }
  return false;
}

}  // namespace

std::size_t nearestView(const Eigen::Isometry3d& culled,
                        const std::vector<Eigen::Isometry3d>& candidates) {
  std::size_t best = 0;
  double best_score = std::numeric_limits<double>::max();
  const Eigen::Vector3d axis = culled.linear().col(2);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const double distance = (candidates[k].translation() - culled.translation()).norm();
    const double turn = 1.0 - axis.dot(candidates[k].linear().col(2));
    const double score = distance + 0.5 * turn;
    if (score < best_score) {
      best_score = score;
      best = k;
    }
  }
  return best;
}

void foldInto(KeyFrameCloud& into, const Eigen::Isometry3d& T_w_into, const KeyFrameCloud& from,
              const Eigen::Isometry3d& T_w_from, double voxel_size, const core::Camera& camera) {
  const Eigen::Isometry3d T_into_from = T_w_into.inverse() * T_w_from;
  const double cell_size = kSameSurfaceVoxels * voxel_size;
  const std::vector<std::uint64_t> occupied = occupiedCells(into, cell_size);
  const FreeSpaceView free_space(camera, into);
  LabelledCloud unseen;
  for (const LabelledCloud* layer : {&from.static_points, &from.folded_points}) {
    const LabelledCloud moved = transformed(*layer, T_into_from);
    for (std::size_t i = 0; i < moved.size(); ++i) {
      if (nearOccupied(cellOf(moved.points[i], cell_size), occupied)) continue;
      if (free_space.seesThrough(moved.points[i])) continue;
      unseen.add(moved.points[i], moved.colours[i], moved.labels[i], moved.instances[i]);
    }
  }
  const LabelledCloud unseen_points = voxelDownsample(unseen, voxel_size);
  // Grown exactly, not by doubling: the live keyframe keeps these points as long as it lives.
  into.folded_points.reserve(into.folded_points.size() + unseen_points.size());
  into.folded_points.append(unseen_points);
}

}  // namespace segslam::dense
