#include "segslam/dense/label_segments.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "segslam/core/semantic_class.h"
#include "segslam/dense/voxel_key.h"

namespace segslam::dense {

namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t root(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

// The 13 neighbours of a cell that come after it, so that each touching pair is visited once.
const std::vector<Eigen::Vector3i>& forwardNeighbours() {
  static const std::vector<Eigen::Vector3i> offsets = [] {
    std::vector<Eigen::Vector3i> result;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const Eigen::Vector3i offset(dx, dy, dz);
          if (std::make_tuple(dx, dy, dz) > std::make_tuple(0, 0, 0)) result.push_back(offset);
        }
      }
    }
    return result;
  }();
  return offsets;
}

// The segments of the points at `indices`, which all have one label and instance id.
std::vector<LabelSegment> segmentsOfLabel(const LabelledCloud& cloud, std::uint8_t label,
                                          const std::vector<std::size_t>& indices, double cell_size,
                                          std::size_t min_points) {
  std::unordered_map<std::uint64_t, std::size_t> cell_index;
  std::vector<Eigen::Vector3i> cells;
  std::vector<std::size_t> cell_of_point(indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const Eigen::Vector3i cell = cellOf(cloud.points[indices[k]], cell_size);
    const auto [it, inserted] = cell_index.try_emplace(packCell(cell), cells.size());
    if (inserted) cells.push_back(cell);
    cell_of_point[k] = it->second;
  }
  UnionFind components(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (const Eigen::Vector3i& offset : forwardNeighbours()) {
      const auto it = cell_index.find(packCell(cells[c] + offset));
      if (it != cell_index.end()) components.join(c, it->second);
    }
  }
  std::map<std::size_t, LabelSegment> by_root;  // roots are smallest cell indices: point order
  for (std::size_t k = 0; k < indices.size(); ++k) {
    by_root[components.root(cell_of_point[k])].indices.push_back(indices[k]);
  }
  for (std::size_t c = 0; c < cells.size(); ++c) {
    by_root[components.root(c)].cells.push_back(packCell(cells[c]));
  }
  std::vector<LabelSegment> segments;
  for (auto& [root, segment] : by_root) {
    if (segment.indices.size() < min_points) continue;
    segment.label = label;
    segment.instance = cloud.instances[segment.indices.front()];
    std::sort(segment.cells.begin(), segment.cells.end());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    segment.min = segment.max = cloud.points[segment.indices.front()];
    for (std::size_t i : segment.indices) {
      sum += cloud.points[i].cast<double>();
      segment.min = segment.min.cwiseMin(cloud.points[i]);
      segment.max = segment.max.cwiseMax(cloud.points[i]);
    }
    segment.centroid = (sum / static_cast<double>(segment.indices.size())).cast<float>();
    segments.push_back(std::move(segment));
  }
  return segments;
}

}  // namespace

bool isObjectLabel(std::uint8_t label) {
  using core::SemanticClass;
  const auto semantic_class = static_cast<SemanticClass>(label);
  return semantic_class != SemanticClass::kNone && semantic_class != SemanticClass::kWall &&
         semantic_class != SemanticClass::kFloor && semantic_class != SemanticClass::kCeiling;
}

float boundsGap(const LabelSegment& a, const LabelSegment& b) {
  const Eigen::Vector3f gap =
      (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(Eigen::Vector3f::Zero());
  return gap.norm();
}

std::vector<LabelSegment> segmentByLabel(const LabelledCloud& cloud, double cell_size,
                                         std::size_t min_points) {
  // Points of one label with different instance ids are different objects even where they touch.
  std::map<std::pair<std::uint8_t, std::uint16_t>, std::vector<std::size_t>> by_instance;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (isObjectLabel(cloud.labels[i]))
      by_instance[{cloud.labels[i], cloud.instances[i]}].push_back(i);
  }
  std::vector<LabelSegment> segments;
  for (const auto& [label_instance, indices] : by_instance) {
    auto label_segments =
        segmentsOfLabel(cloud, label_instance.first, indices, cell_size, min_points);
    std::move(label_segments.begin(), label_segments.end(), std::back_inserter(segments));
  }
  return segments;
}

}  // namespace segslam::dense
