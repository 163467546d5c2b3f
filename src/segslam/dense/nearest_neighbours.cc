#include "segslam/dense/nearest_neighbours.h"

#include <open3d/geometry/KDTreeFlann.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "segslam/dense/open3d_conversion.h"

namespace segslam::dense {

struct NearestNeighbours::Index {
  // The tree searches the cloud's own coordinates (Open3D 0.16 does not copy them), so the cloud
  // lives as long as the tree.
  open3d::geometry::PointCloud cloud;
  open3d::geometry::KDTreeFlann tree;
};

NearestNeighbours::NearestNeighbours(const std::vector<Eigen::Vector3f>& points)
    : index_(std::make_unique<Index>()) {
  index_->cloud = toOpen3d(points);
  if (!points.empty()) index_->tree.SetGeometry(index_->cloud);
}

NearestNeighbours::~NearestNeighbours() = default;

bool NearestNeighbours::anyWithin(const Eigen::Vector3f& query, double radius) const {
  if (index_->cloud.points_.empty()) return false;
  std::vector<int> indices;
  std::vector<double> squared_distances;
  const Eigen::Vector3d q = query.cast<double>();
  return index_->tree.SearchHybrid(q, radius, 1, indices, squared_distances) > 0;
}

std::size_t NearestNeighbours::countWithin(const std::vector<Eigen::Vector3f>& queries,
                                           double radius) const {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, queries.size(), 4096), std::size_t{0},
      [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          if (anyWithin(queries[i], radius)) ++count;
        }
        return count;
      },
      std::plus<>());
}

}  // namespace segslam::dense
