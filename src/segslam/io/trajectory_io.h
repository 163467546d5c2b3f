#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "segslam/core/trajectory.h"

namespace segslam::io {

// Reads a TUM trajectory file: `timestamp tx ty tz qx qy qz qw` per line, camera-to-world.
// Throws util::Error naming file and line for malformed lines, non-finite numbers, zero or
// non-finite quaternions, and for an empty file. Duplicated timestamps and lines out of order are
// read as the TUM benchmark tools read them (the later line of a timestamp wins, the poses are
// sorted by time; see util::keyRowsByTimestamp), with one warning naming the file: the
// benchmark's own ground truth has them (rgbd_dataset_freiburg2_desk, line 10863).
core::Trajectory readTumTrajectory(const std::filesystem::path& file);

// The same for the text of such a file; `name` is the file named in error messages.
core::Trajectory parseTumTrajectory(std::string_view text, const std::filesystem::path& name);

// Writes a TUM trajectory file (timestamps with 6 decimals, values with 9), creating parent
// folders as needed; throws util::Error naming the file or folder that cannot be written.
void writeTumTrajectory(const std::filesystem::path& file, const core::Trajectory& trajectory,
                        const std::string& header_comment = "");

}  // namespace segslam::io
