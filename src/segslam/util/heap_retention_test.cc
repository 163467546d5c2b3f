#include "segslam/util/heap_retention.h"

#include <gtest/gtest.h>

namespace segslam::util {
namespace {

#if defined(__GLIBC__)
TEST(HeapRetention, GlibcAcceptsTheThresholds) {
  EXPECT_TRUE(boundHeapRetention());
  EXPECT_TRUE(boundHeapRetention()) << "calling it again changes nothing";
}
#endif

}  // namespace
}  // namespace segslam::util
