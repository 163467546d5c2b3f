#include "segslam/util/heap_retention.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace segslam::util {

bool boundHeapRetention() {
#if defined(__GLIBC__)
  constexpr int kMmapThreshold = 32 << 20;  // glibc's largest
  constexpr int kTrimThreshold = 512 << 10;
  return mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 &&
         mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
#else
  return false;
#endif
}

}  // namespace segslam::util
