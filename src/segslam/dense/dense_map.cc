#include "segslam/dense/dense_map.h"

#include <open3d/geometry/PointCloud.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "segslam/dense/open3d_conversion.h"
#include "segslam/dense/ply_io.h"
#include "segslam/util/error.h"

namespace segslam::dense {

namespace {

nlohmann::json vectorJson(const Eigen::Vector3f& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json boxJson(const OrientedBox& box) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({box.axes(r, 0), box.axes(r, 1), box.axes(r, 2)});
  return {{"centre", vectorJson(box.centre)}, {"extent", vectorJson(box.extent)}, {"axes", rows}};
}

nlohmann::json objectJson(const MapObject& object, const std::string& file) {
  return {{"id", object.id},
          {"label", object.label},
          {"instance", object.instance},
          {"dynamic", object.dynamic},
          {"confidence", object.confidence},
          {"keyframes", object.keyframes},
          {"points", object.points.size()},
          {"centroid", vectorJson(object.centroid)},
          {"bbox_min", vectorJson(object.bbox_min)},
          {"bbox_max", vectorJson(object.bbox_max)},
          {"oriented_box", boxJson(object.box)},
          {"file", file}};
}

}  // namespace

LabelledCloud removeOutliers(const LabelledCloud& cloud, const CloudCleaningOptions& options) {
  if (options.outlier_neighbours <= 0 ||
      cloud.size() <= static_cast<std::size_t>(options.outlier_neighbours)) {
    return cloud;
  }
  const auto [kept_cloud, kept] =
      toOpen3d(cloud.points)
          .RemoveStatisticalOutliers(static_cast<std::size_t>(options.outlier_neighbours),
                                     options.outlier_std_ratio);
  return cloud.select(kept);
}

void writeDenseMap(const DenseMap& map, const std::filesystem::path& folder) {
  std::error_code ignored;
  std::filesystem::remove_all(folder / "objects", ignored);
  writePly(folder / "static.ply", map.static_points);
  writePly(folder / "dynamic.ply", map.dynamic_points);
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& object : map.objects) {
    const std::string file = "objects/" + object.id + ".ply";
    writePly(folder / file, object.points);
    objects.push_back(objectJson(object, file));
  }
  const auto index = folder / "objects.json";
  std::ofstream out(index);
  out << nlohmann::json{{"voxel_size", map.voxel_size}, {"objects", objects}}.dump(1) << "\n";
  if (!out) util::failAt(index, "cannot write");
}

}  // namespace segslam::dense
