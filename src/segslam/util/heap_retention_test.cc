#include "segslam/util/heap_retention.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <memory>
#include <thread>
#include <vector>

#include "segslam/util/sanitizer.h"

namespace segslam::util {
namespace {

// Under AddressSanitizer malloc is the sanitizer's, which takes no glibc thresholds.
#if defined(__GLIBC__) && !defined(SEGSLAM_ADDRESS_SANITIZER)
constexpr bool kGlibcAllocator = true;
#else
constexpr bool kGlibcAllocator = false;
#endif

double residentMegabytes() {
  std::ifstream statm("/proc/self/statm");
  long total_pages = 0;
  long resident_pages = 0;
  statm >> total_pages >> resident_pages;
  return static_cast<double>(resident_pages) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

TEST(HeapRetention, OnlyGlibcsAllocatorTakesTheThresholds) {
  EXPECT_EQ(boundHeapRetention(), kGlibcAllocator);
  EXPECT_EQ(boundHeapRetention(), kGlibcAllocator) << "calling it again changes nothing";
}

TEST(HeapRetention, TrimGivesBackFreePagesBelowABlockInUse) {
  if (!kGlibcAllocator) GTEST_SKIP() << "malloc is not glibc's";
  // 32 MB in 64 kB blocks (below any mmap threshold, so in the heap), touched; all freed but the
  // last, which keeps the free space off the heap's top, where the trim threshold cannot reach.
  constexpr std::size_t kBlock = 64 << 10;
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int i = 0; i < 512; ++i) {
    blocks.emplace_back(new char[kBlock]);
    std::memset(blocks.back().get(), 1, kBlock);
  }
  const std::unique_ptr<char[]> last = std::move(blocks.back());
  blocks.clear();
  const double before = residentMegabytes();
  EXPECT_TRUE(trimHeaps());
  EXPECT_LT(residentMegabytes(), before - 16.0);
}

TEST(HeapRetention, TrimmerTrimsUntilItIsDestroyed) {
  HeapTrimmer trimmer(std::chrono::milliseconds(2));
  EXPECT_EQ(trimmer.active(), kGlibcAllocator);
  if (!kGlibcAllocator) return;
  for (int wait = 0; wait < 5000 && trimmer.trims() < 3; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_GE(trimmer.trims(), 3U);
}

TEST(HeapRetention, TrimmerStopsAtOnceWhenDestroyed) {
  // An hour between trims: destruction must not wait for the next one.
  const HeapTrimmer trimmer(std::chrono::hours(1));
  EXPECT_EQ(trimmer.active(), kGlibcAllocator);
}

}  // namespace
}  // namespace segslam::util
