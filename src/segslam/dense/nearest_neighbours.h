#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace segslam::dense {

// Radius queries against a fixed point set (Open3D's k-d tree), for comparing clouds.
class NearestNeighbours {
 public:
  explicit NearestNeighbours(const std::vector<Eigen::Vector3f>& points);
  ~NearestNeighbours();
  NearestNeighbours(const NearestNeighbours&) = delete;
  NearestNeighbours& operator=(const NearestNeighbours&) = delete;

  // Whether a point of the set lies within `radius` of `query` (always false for an empty set).
  [[nodiscard]] bool anyWithin(const Eigen::Vector3f& query, double radius) const;
  // How many of `queries` have a point of the set within `radius`.
  [[nodiscard]] std::size_t countWithin(const std::vector<Eigen::Vector3f>& queries,
                                        double radius) const;

 private:
  struct Index;
  std::unique_ptr<Index> index_;
};

}  // namespace segslam::dense
