#pragma once

#include <filesystem>

namespace segslam::util {

// Creates `folder` and its parents for a command's output, or throws Error naming it and why, e.g.
// "cannot create output folder /data/file.txt/run: Not a directory"; also when it is there but
// cannot be written into ("cannot write into output folder ...: Read-only file system"). Without
// this, a bad --out surfaced as the standard library's "filesystem error" text, or not at all
// (std::ofstream fails silently).
void createOutputFolder(const std::filesystem::path& folder);

// createOutputFolder() for the folder that `file` is to be written into; nothing for a bare file
// name (the working folder).
void createFolderFor(const std::filesystem::path& file);

}  // namespace segslam::util
