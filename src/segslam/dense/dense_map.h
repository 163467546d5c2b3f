#pragma once

#include <filesystem>
#include <vector>

#include "segslam/dense/labelled_cloud.h"
#include "segslam/dense/object_map.h"

namespace segslam::dense {

// The map of a run, in the world frame of its trajectory.
struct DenseMap {
  double voxel_size = 0.01;
  LabelledCloud static_points;
  LabelledCloud dynamic_points;    // where dynamic objects were seen, for checking the masks
  std::vector<MapObject> objects;  // static objects, then dynamic ones
  // Points of an earlier session's map (MapBuilder::setEarlierMap) this run saw through.
  std::size_t earlier_points_removed = 0;
};

struct CloudCleaningOptions {
  // Open3D's statistical outlier removal: a point goes when its mean distance to its
  // `outlier_neighbours` nearest neighbours exceeds the cloud's mean by `outlier_std_ratio`
  // standard deviations. 0 neighbours: no removal. 8 rather than 16 takes 30 % less time with
  // the same map quality (bench/results/maps.md, README).
  int outlier_neighbours = 8;
  double outlier_std_ratio = 2.0;
};

// Statistical outlier removal (see CloudCleaningOptions), keeping the order of the points.
LabelledCloud removeOutliers(const LabelledCloud& cloud, const CloudCleaningOptions& options);

// Writes the map folder: static.ply, dynamic.ply (present even without points), objects.json
// ({"voxel_size", "objects": [{"id", "label", "instance", "dynamic", "confidence", "keyframes",
// "points", "centroid", "bbox_min", "bbox_max", "oriented_box": {"centre", "extent", "axes"},
// "file"}]}, documented in docs/usage.md) and objects/<id>.ply. Earlier object files are removed
// first so that the folder holds exactly this map. Throws util::Error naming a file that cannot
// be written.
void writeDenseMap(const DenseMap& map, const std::filesystem::path& folder);

}  // namespace segslam::dense
