#pragma once

#include <open3d/geometry/PointCloud.h>

#include <Eigen/Core>
#include <vector>

// Conversions to Open3D's point cloud, kept inside the dense module's .cc files so that the rest
// of the project does not compile Open3D's headers.
namespace segslam::dense {

open3d::geometry::PointCloud toOpen3d(const std::vector<Eigen::Vector3f>& points);

}  // namespace segslam::dense
