#include "segslam/util/heap_retention.h"

#include <gtest/gtest.h>

namespace segslam::util {
namespace {

// Under AddressSanitizer malloc is the sanitizer's, which takes no glibc thresholds.
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
constexpr bool kGlibcAllocator = true;
#else
constexpr bool kGlibcAllocator = false;
#endif

TEST(HeapRetention, OnlyGlibcsAllocatorTakesTheThresholds) {
  EXPECT_EQ(boundHeapRetention(), kGlibcAllocator);
  EXPECT_EQ(boundHeapRetention(), kGlibcAllocator) << "calling it again changes nothing";
}

}  // namespace
}  // namespace segslam::util
