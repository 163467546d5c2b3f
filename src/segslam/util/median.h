#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace segslam::util {

// The median of a non-empty vector (the upper one for an even count), found by partial sorting:
// the vector's order is changed.
template <typename T>
T medianInPlace(std::vector<T>& values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace segslam::util
