#include "segslam/occupancy/occupancy_map.h"

#include <fmt/format.h>
#include <octomap/OcTree.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>

#include "segslam/occupancy/octree_data.h"
#include "segslam/util/error.h"

namespace segslam::occupancy {

namespace {

octomap::point3d toOctomap(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

octomap::point3d toOctomap(const Eigen::Vector3f& p) { return {p.x(), p.y(), p.z()}; }

Eigen::Vector3d fromOctomap(const octomap::point3d& p) { return {p.x(), p.y(), p.z()}; }

std::unique_ptr<octomap::OcTree> makeTree(const OccupancyOptions& options) {
  if (!(options.resolution_m > 0.0)) {
    throw util::Error(
        fmt::format("the occupancy resolution must be positive, not {}", options.resolution_m));
  }
  auto tree = std::make_unique<octomap::OcTree>(options.resolution_m);
  tree->setProbHit(options.probability_hit);
  tree->setProbMiss(options.probability_miss);
  tree->setClampingThresMin(options.clamping_min);
  tree->setClampingThresMax(options.clamping_max);
  return tree;
}

// The header of a binary octree file, as OctoMap writes it: its first line, then `key value`
// lines up to `data`, among them `id OcTree`, the node count `size` and a positive `res`.
struct OctreeHeader {
  std::size_t size = 0;
  double resolution = 0.0;
};

constexpr const char* kOctreeFirstLine = "# Octomap OcTree binary file";

// Reads the header, leaving `in` at the data. OctoMap's own readBinary would say what is wrong
// on the standard error in lines of its own (and narrate a good read).
OctreeHeader readOctreeHeader(std::istream& in, const std::filesystem::path& file) {
  std::string line;
  if (!std::getline(in, line) || line.rfind(kOctreeFirstLine, 0) != 0) {
    util::failAt(file, "not an OctoMap binary occupancy map (.bt)");
  }
  OctreeHeader header;
  bool octree = false;
  bool data = false;
  int number = 1;
  while (!data && std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string key;
    fields >> key;
    if (key == "data") {
      data = true;
    } else if (key == "id") {
      std::string id;
      fields >> id;
      if (id != "OcTree") util::failAt(file, number, "an octree of type " + id + ", not OcTree");
      octree = true;
    } else if (key == "size" && !(fields >> header.size)) {
      util::failAt(file, number, "the size must be a node count");
    } else if (key == "res" && !(fields >> header.resolution && header.resolution > 0.0)) {
      util::failAt(file, number, "the resolution must be a positive number");
    }
  }
  if (!data || !octree || !(header.resolution > 0.0)) {
    util::failAt(file,
                 "not an OctoMap binary occupancy map (.bt): its header lacks id, res or data");
  }
  return header;
}

}  // namespace

OccupancyMap::OccupancyMap(const OccupancyOptions& options)
    : options_(options), tree_(makeTree(options)) {}

OccupancyMap::~OccupancyMap() = default;
OccupancyMap::OccupancyMap(OccupancyMap&&) noexcept = default;
OccupancyMap& OccupancyMap::operator=(OccupancyMap&&) noexcept = default;

void OccupancyMap::insert(const Scan& scan) {
  const octomap::point3d origin = toOctomap(scan.origin);
  const double max_range = options_.max_range_m > 0.0 ? options_.max_range_m : INFINITY;
  octomap::KeySet occupied;
  octomap::KeySet free;
  octomap::KeyRay ray;
  // Rays are cast to voxels, not to points: the ends of a scan are far denser than the map.
  octomap::KeySet ends_seen;
  const auto castTo = [&](const Eigen::Vector3f& end_point, bool surface) {
    octomap::point3d end = toOctomap(end_point);
    const octomap::point3d direction = end - origin;
    const double range = direction.norm();
    if (!(range > 0.0)) return;
    const bool within = range <= max_range;
    if (!within) end = origin + direction * static_cast<float>(max_range / range);
    octomap::OcTreeKey end_key;
    if (!tree_->coordToKeyChecked(end, end_key)) return;
    if (!ends_seen.insert(end_key).second) return;
    if (surface && within) occupied.insert(end_key);
    const octomap::point3d to_end = tree_->keyToCoord(end_key) - origin;
    const double length = to_end.norm();
    const double margin = surface ? options_.surface_margin_m : 0.0;
    if (length <= margin) return;
    const octomap::point3d stop = origin + to_end * static_cast<float>((length - margin) / length);
    if (tree_->computeRayKeys(origin, stop, ray)) free.insert(ray.begin(), ray.end());
  };
  // Surfaces first: a voxel that one ray ends in and another passes through stays occupied.
  for (const auto& end : scan.static_ends) castTo(end, true);
  for (const auto& end : scan.dynamic_ends) castTo(end, false);
  for (const auto& key : free) {
    if (occupied.count(key) == 0) tree_->updateNode(key, false, true);
  }
  for (const auto& key : occupied) tree_->updateNode(key, true, true);
  tree_->updateInnerOccupancy();
}

void OccupancyMap::loadEarlier(const std::filesystem::path& file) {
  auto earlier = readOctree(file);
  if (std::abs(earlier->getResolution() - options_.resolution_m) > 1e-9) {
    util::failAt(file, fmt::format("an occupancy map of {} m voxels, not {} m",
                                   earlier->getResolution(), options_.resolution_m));
  }
  const float occupied = octomap::logodds(options_.earlier_belief_occupied);
  const float free = octomap::logodds(options_.earlier_belief_free);
  for (auto it = earlier->begin_leafs(); it != earlier->end_leafs(); ++it) {
    it->setLogOdds(earlier->isNodeOccupied(*it) ? occupied : free);
  }
  earlier->updateInnerOccupancy();
  earlier->setProbHit(options_.probability_hit);
  earlier->setProbMiss(options_.probability_miss);
  earlier->setClampingThresMin(options_.clamping_min);
  earlier->setClampingThresMax(options_.clamping_max);
  tree_ = std::move(earlier);
}

void OccupancyMap::write(const std::filesystem::path& file) const {
  // The binary format holds each voxel's maximum-likelihood state; a pruned copy is written.
  octomap::OcTree copy(*tree_);
  copy.toMaxLikelihood();
  copy.prune();
  std::ofstream out(file, std::ios::binary);
  out << kOctreeFirstLine << "\n# written by segslam\n#\nid " << copy.getTreeType() << "\nsize "
      << copy.size() << "\nres " << copy.getResolution() << "\ndata\n";
  copy.writeBinaryData(out);
  if (!out.flush()) util::failAt(file, "cannot write");
}

double OccupancyMap::resolution() const { return tree_->getResolution(); }

OccupancyCounts OccupancyMap::counts() const {
  return {voxelCentres(*tree_, true).size(), voxelCentres(*tree_, false).size()};
}

std::vector<Eigen::Vector3d> OccupancyMap::occupiedVoxels() const {
  return voxelCentres(*tree_, true);
}

std::vector<Eigen::Vector3d> OccupancyMap::freeVoxels() const {
  return voxelCentres(*tree_, false);
}

std::unique_ptr<octomap::OcTree> readOctree(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) util::failAt(file, "file not found");
  std::ifstream in(file, std::ios::binary);
  const OctreeHeader header = readOctreeHeader(in, file);
  auto tree = std::make_unique<octomap::OcTree>(header.resolution);
  if (header.size == 0) return tree;
  std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const OctreeDataCheck check = checkOctreeData(data, tree->getTreeDepth());
  if (!check.extent) {
    util::failAt(file, fmt::format("its data is cut short or damaged ({} after {} of the {} "
                                   "nodes its header gives)",
                                   check.problem, check.nodes_read, header.size));
  }
  if (check.extent->nodes != header.size) {
    util::failAt(file, fmt::format("its data is cut short or damaged ({} nodes, its header "
                                   "gives {})",
                                   check.extent->nodes, header.size));
  }
  data.resize(check.extent->bytes);
  std::istringstream nodes(std::move(data));
  tree->readBinaryData(nodes);
  return tree;
}

std::vector<Eigen::Vector3d> voxelCentres(const octomap::OcTree& tree, bool occupied) {
  std::vector<Eigen::Vector3d> centres;
  const double resolution = tree.getResolution();
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    if (tree.isNodeOccupied(*it) != occupied) continue;
    const double size = it.getSize();
    const int per_side = static_cast<int>(std::lround(size / resolution));
    const Eigen::Vector3d corner =
        fromOctomap(it.getCoordinate()) - Eigen::Vector3d::Constant(size / 2.0 - resolution / 2.0);
    for (int i = 0; i < per_side; ++i) {
      for (int j = 0; j < per_side; ++j) {
        for (int k = 0; k < per_side; ++k) {
          centres.push_back(corner + resolution * Eigen::Vector3d(i, j, k));
        }
      }
    }
  }
  return centres;
}

VoxelState stateAt(const octomap::OcTree& tree, const Eigen::Vector3d& point) {
  const octomap::OcTreeNode* node = tree.search(point.x(), point.y(), point.z());
  if (node == nullptr) return VoxelState::kUnknown;
  return tree.isNodeOccupied(node) ? VoxelState::kOccupied : VoxelState::kFree;
}

}  // namespace segslam::occupancy
