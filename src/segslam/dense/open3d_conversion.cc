#include "segslam/dense/open3d_conversion.h"

#include <open3d/utility/Logging.h>

namespace segslam::dense {

open3d::geometry::PointCloud toOpen3d(const std::vector<Eigen::Vector3f>& points) {
  // Open3D reports progress of its algorithms on stdout at its default level; only its
  // warnings belong in our output.
  static const bool quiet = [] {
    open3d::utility::SetVerbosityLevel(open3d::utility::VerbosityLevel::Warning);
    return true;
  }();
  (void)quiet;
  open3d::geometry::PointCloud cloud;
  cloud.points_.reserve(points.size());
  for (const auto& p : points) cloud.points_.push_back(p.cast<double>());
  return cloud;
}

}  // namespace segslam::dense
