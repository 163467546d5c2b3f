// io::parseImageList (rgb.txt, depth.txt, mask.txt, ...) and io::parseAssociationList
// (associations.txt) either throw util::Error or return entries in strictly increasing time.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "segslam/io/image_list.h"
#include "segslam/util/error.h"

namespace {

using segslam::fuzz::check;

void checkEntry(const segslam::io::ImageListEntry& entry) {
  check(entry.line > 0, "entries have a line number");
  check(std::isfinite(entry.timestamp), "timestamps are finite");
  check(!entry.path.empty(), "entries have a path");
}

void checkImageList(std::string_view text) {
  try {
    const auto entries = segslam::io::parseImageList(text, "rgb.txt");
    for (std::size_t i = 0; i < entries.size(); ++i) {
      checkEntry(entries[i]);
      if (i > 0) check(entries[i].timestamp > entries[i - 1].timestamp, "timestamps increase");
    }
  } catch (const segslam::util::Error&) {
    // Rejected input, with a message: the expected outcome for most inputs.
  }
}

void checkAssociationList(std::string_view text) {
  try {
    const auto entries = segslam::io::parseAssociationList(text, "associations.txt");
    std::vector<double> depth_stamps;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      depth_stamps.push_back(entries[i].depth.timestamp);
      checkEntry(entries[i].rgb);
      checkEntry(entries[i].depth);
      check(entries[i].rgb.line == entries[i].depth.line, "both halves come from one line");
      if (i > 0) {
        check(entries[i].rgb.timestamp > entries[i - 1].rgb.timestamp, "rgb timestamps increase");
      }
    }
    std::sort(depth_stamps.begin(), depth_stamps.end());
    check(std::adjacent_find(depth_stamps.begin(), depth_stamps.end()) == depth_stamps.end(),
          "depth timestamps are unique");
  } catch (const segslam::util::Error&) {
    // Rejected input, with a message: the expected outcome for most inputs.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  checkImageList(text);
  checkAssociationList(text);
  return 0;
}
