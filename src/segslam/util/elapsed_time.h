#pragma once

#include <chrono>

namespace segslam::util {

// Wall time since `start` in milliseconds: the unit every timing in logs and summaries uses.
inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace segslam::util
