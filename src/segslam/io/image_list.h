#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

namespace segslam::io {

// One line of a TUM image list (rgb.txt, depth.txt, mask.txt, labels.txt, instances.txt):
// `timestamp path`, the path relative to the dataset folder.
struct ImageListEntry {
  int line = 0;  // 1-based line in the list file, for error messages
  double timestamp = 0.0;
  std::filesystem::path path;
};

// Reads an image list. Throws util::Error naming the file and line for a line without exactly
// two fields or a timestamp that is not a finite number. Duplicated timestamps and lines out of
// order are read as the TUM tools' associate.py reads them (the later line of a timestamp wins,
// the entries are sorted by time; see util::keyRowsByTimestamp), with one warning naming the
// file. An empty list is returned as such: the caller knows whether that is an error.
std::vector<ImageListEntry> readImageList(const std::filesystem::path& file);

// The same for the text of such a file; `name` is the file named in error messages.
std::vector<ImageListEntry> parseImageList(std::string_view text,
                                           const std::filesystem::path& name);

// One line of associations.txt as written by the TUM tools' associate.py:
// `t_rgb rgb_path t_depth depth_path`.
struct AssociationEntry {
  ImageListEntry rgb;
  ImageListEntry depth;
};

// Reads associations.txt: its colour timestamps order the frames and are keyed like an image
// list's (the later line of a duplicated one wins, the lines are sorted, with a warning); then no
// depth timestamp may appear twice. The depth timestamps need not increase: the TUM greedy
// association can pair two close colour images with their depth images crosswise.
std::vector<AssociationEntry> readAssociationList(const std::filesystem::path& file);

std::vector<AssociationEntry> parseAssociationList(std::string_view text,
                                                   const std::filesystem::path& name);

}  // namespace segslam::io
