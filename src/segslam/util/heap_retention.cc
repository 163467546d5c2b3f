#include "segslam/util/heap_retention.h"

#include "segslam/util/sanitizer.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace segslam::util {

namespace {

// Under AddressSanitizer malloc is the sanitizer's: glibc's settings and trims reach nothing.
constexpr bool kGlibcAllocator =
#if defined(__GLIBC__) && !defined(SEGSLAM_ADDRESS_SANITIZER)
    true;
#else
    false;
#endif

}  // namespace

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

bool trimHeaps() {
  if constexpr (!kGlibcAllocator) return false;
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  return true;
}

HeapTrimmer::HeapTrimmer(std::chrono::milliseconds interval) {
  if (kGlibcAllocator) thread_ = std::thread([this, interval] { run(interval); });
}

HeapTrimmer::~HeapTrimmer() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_requested_.notify_all();
  thread_.join();
}

std::size_t HeapTrimmer::trims() {
  std::lock_guard lock(mutex_);
  return trims_;
}

void HeapTrimmer::run(std::chrono::milliseconds interval) {
  std::unique_lock lock(mutex_);
  while (!stop_requested_.wait_for(lock, interval, [this] { return stopping_; })) {
    lock.unlock();
    trimHeaps();
    lock.lock();
    ++trims_;
  }
}

}  // namespace segslam::util
