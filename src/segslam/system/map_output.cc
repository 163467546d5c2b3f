#include "segslam/system/map_output.h"

namespace segslam::system {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

MapSummary buildAndWriteMap(dense::MapBuilder& builder, const core::Trajectory& keyframe_poses,
                            const std::filesystem::path& folder,
                            const OccupancyOutputOptions& occupancy) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<OccupancyOutput> occupancy_output;
  if (occupancy.build) occupancy_output.emplace(occupancy);
  dense::KeyFrameScanSink scans;
  if (occupancy_output) {
    scans = [&](const Eigen::Vector3d& origin, const dense::LabelledCloud& static_points,
                const dense::LabelledCloud& dynamic_points) {
      occupancy_output->scan(origin, static_points, dynamic_points);
    };
  }
  const dense::DenseMap map = builder.build(keyframe_poses, scans);
  dense::writeDenseMap(map, folder);
  MapSummary summary;
  if (occupancy_output) summary.occupancy = occupancy_output->write(folder, keyframe_poses);
  summary.keyframes = builder.numKeyFrames();
  summary.static_points = map.static_points.size();
  summary.dynamic_points = map.dynamic_points.size();
  summary.objects = map.objects.size();
  summary.earlier_points_removed = map.earlier_points_removed;
  summary.timings = builder.timings();
  summary.build_seconds = secondsSince(start);
  return summary;
}

nlohmann::json toJson(const MapSummary& summary) {
  return {{"keyframes", summary.keyframes},
          {"static_points", summary.static_points},
          {"dynamic_points", summary.dynamic_points},
          {"objects", summary.objects},
          {"earlier_points_removed", summary.earlier_points_removed},
          {"keyframe_seconds", summary.keyFrameSeconds()},
          {"build_seconds", summary.build_seconds},
          {"timings",
           {{"back_projection_cpu_s", summary.timings.back_projection},
            {"keyframe_voxels_cpu_s", summary.timings.keyframe_voxels},
            {"merging_s", summary.timings.merging},
            {"outlier_removal_s", summary.timings.outlier_removal},
            {"objects_s", summary.timings.objects}}},
          {"occupancy", summary.occupancy ? toJson(*summary.occupancy) : nlohmann::json(nullptr)}};
}

}  // namespace segslam::system
