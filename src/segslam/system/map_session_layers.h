#pragma once

#include <filesystem>
#include <vector>

#include "segslam/map/map_file.h"

namespace segslam::system {

// The viewer's layer per session of a saved map (segslam view): for each session n, the map
// points it made as session_<n>_points.ply and its keyframes' camera centres as
// session_<n>_keyframes.ply, in `folder` (created), coloured by session. Returns the files
// written; throws util::Error naming a file that cannot be written.
std::vector<std::filesystem::path> writeSessionLayers(const map::MapFileContents& contents,
                                                      const std::filesystem::path& folder);

}  // namespace segslam::system
