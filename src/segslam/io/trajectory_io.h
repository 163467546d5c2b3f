#pragma once

#include <filesystem>

#include "segslam/core/trajectory.h"

namespace segslam::io {

// Reads a TUM trajectory file: `timestamp tx ty tz qx qy qz qw` per line, camera-to-world.
// Throws util::Error naming file and line for malformed lines, non-finite numbers, zero
// quaternions, and timestamps that are duplicated or out of order; also for an empty file.
core::Trajectory readTumTrajectory(const std::filesystem::path& file);

// Writes a TUM trajectory file (timestamps with 6 decimals, values with 9), creating parent
// folders as needed.
void writeTumTrajectory(const std::filesystem::path& file, const core::Trajectory& trajectory,
                        const std::string& header_comment = "");

}  // namespace segslam::io
