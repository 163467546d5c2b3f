#pragma once

// Invariant checks for the fuzz targets: a violated invariant aborts, which libFuzzer reports as
// a crash with the input that caused it.

#include <cstdio>
#include <cstdlib>

namespace segslam::fuzz {

inline void check(bool condition, const char* invariant) {
  if (!condition) {
    std::fprintf(stderr, "fuzz invariant violated: %s\n", invariant);
    std::abort();
  }
}

}  // namespace segslam::fuzz
