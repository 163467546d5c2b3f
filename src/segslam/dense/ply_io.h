#pragma once

#include <filesystem>

#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

// Writes a binary little-endian PLY with one vertex element (float x, y, z; uchar red, green,
// blue), as Open3D, MeshLab and CloudCompare read it. Labels and instances are not stored: the
// object map keeps them as separate files. Creates the parent folder; throws util::Error naming
// the file when it cannot be written.
void writePly(const std::filesystem::path& file, const LabelledCloud& cloud);

// Reads the vertices of a binary little-endian PLY: x, y, z (float or double) and, when present,
// red, green, blue (uchar); other scalar vertex properties are skipped, elements after the
// vertices ignored. Labels and instances are 0. Throws util::Error naming the file for a missing
// file, a malformed header, other formats, list properties in the vertex element, and data
// shorter than the header announces.
LabelledCloud readPly(const std::filesystem::path& file);

}  // namespace segslam::dense
