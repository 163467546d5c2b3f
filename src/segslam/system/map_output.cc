#include "segslam/system/map_output.h"

namespace segslam::system {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

MapSummary buildAndWriteMap(dense::MapBuilder& builder, const core::Trajectory& keyframe_poses,
                            const std::filesystem::path& folder) {
  const auto start = std::chrono::steady_clock::now();
  const dense::DenseMap map = builder.build(keyframe_poses);
  dense::writeDenseMap(map, folder);
  MapSummary summary;
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
            {"objects_s", summary.timings.objects}}}};
}

}  // namespace segslam::system
