#pragma once

// The occupancy map's files in a run's map folder (docs/map_file.md), named once for the writer
// (system::OccupancyOutput), the viewer and the evaluation.
namespace segslam::occupancy {

inline constexpr const char* kOccupancyFile = "occupancy.bt";       // OctoMap binary octree
inline constexpr const char* kFloorGridImage = "occupancy_2d.pgm";  // map_server image
inline constexpr const char* kFloorGridYaml = "occupancy_2d.yaml";  // map_server description
inline constexpr const char* kOccupiedVoxelsFile = "occupancy_occupied.ply";  // voxel centres
inline constexpr const char* kOccupancyInfoFile = "occupancy.json";  // counts, the grid's frame

}  // namespace segslam::occupancy
