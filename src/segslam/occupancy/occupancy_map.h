#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <vector>

namespace octomap {
class OcTree;
}

namespace segslam::occupancy {

struct OccupancyOptions {
  double resolution_m = 0.05;  // voxel edge
  // Rays are cast this far at most; a depth beyond it marks the ray free up to it and nothing
  // occupied. 0 = no limit.
  double max_range_m = 5.0;
  // A ray to a surface clears space up to this much before it: a surface that depth noise and a
  // centimetre of pose error place in the voxel before is not carved away by the next ray (two
  // runs of the same frames: 12.6 % of one's occupied voxels free in the other without a margin,
  // 9.3 % with 0.1 m).
  double surface_margin_m = 0.1;
  // OctoMap's sensor model: the probability that a voxel is occupied after one hit or one miss,
  // and the clamping bounds that keep it able to change its mind.
  double probability_hit = 0.7;
  double probability_miss = 0.4;
  double clamping_min = 0.12;
  double clamping_max = 0.97;
  // An earlier session's voxels are believed this much when they are loaded: one ray of this
  // session through an occupied one clears it, one hit in a free one fills it, so that a chair
  // moved since leaves its old place and shows up at its new one.
  double earlier_belief_occupied = 0.58;
  double earlier_belief_free = 0.45;
};

// What one keyframe saw, in world coordinates: the camera centre and the ends of its rays. A
// static end is a surface (occupied, the ray before it free); a dynamic end is a person or another
// moving object, so the ray up to it is free and the end itself says nothing about the static
// world (where a person walked, the map says free).
struct Scan {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3f> static_ends;
  std::vector<Eigen::Vector3f> dynamic_ends;
};

struct OccupancyCounts {
  std::size_t occupied = 0;  // leaf voxels at the map's resolution
  std::size_t free = 0;
};

// A 3D occupancy map of the static world (an OctoMap octree): free, occupied or unknown space
// for planning. Scans are integrated by ray casting, each ray's voxels updated once per scan.
class OccupancyMap {
 public:
  explicit OccupancyMap(const OccupancyOptions& options = {});
  ~OccupancyMap();
  OccupancyMap(OccupancyMap&&) noexcept;
  OccupancyMap& operator=(OccupancyMap&&) noexcept;

  void insert(const Scan& scan);

  // Starts from an earlier session's map (an OctoMap .bt file of the same world frame and
  // resolution): its occupied and free voxels, believed as OccupancyOptions says. util::Error
  // naming the file when it cannot be read or has another resolution.
  void loadEarlier(const std::filesystem::path& file);

  // Writes the map as OctoMap's binary .bt (maximum-likelihood occupancy, what octovis and
  // bt2vrml read). util::Error naming the file when it cannot be written.
  void write(const std::filesystem::path& file) const;

  [[nodiscard]] double resolution() const;
  [[nodiscard]] OccupancyCounts counts() const;
  // Centres of the occupied (or free) voxels, at the map's resolution.
  [[nodiscard]] std::vector<Eigen::Vector3d> occupiedVoxels() const;
  [[nodiscard]] std::vector<Eigen::Vector3d> freeVoxels() const;
  [[nodiscard]] const octomap::OcTree& tree() const { return *tree_; }

 private:
  OccupancyOptions options_;
  std::unique_ptr<octomap::OcTree> tree_;
};

// Reads an OctoMap .bt file (ours or any other) into an octree; util::Error naming the file when
// it is missing or not a binary octree.
std::unique_ptr<octomap::OcTree> readOctree(const std::filesystem::path& file);

// Centres of the occupied (or free) voxels of an octree at its finest resolution: a pruned leaf
// stands for every voxel of its cube.
std::vector<Eigen::Vector3d> voxelCentres(const octomap::OcTree& tree, bool occupied);

enum class VoxelState { kUnknown, kFree, kOccupied };
[[nodiscard]] VoxelState stateAt(const octomap::OcTree& tree, const Eigen::Vector3d& point);

}  // namespace segslam::occupancy
