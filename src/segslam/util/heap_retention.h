#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>

namespace segslam::util {

// Fixes glibc's heap thresholds for a process that runs for hours. By default glibc raises its
// mmap threshold to the largest block freed so far (up to 32 MB) and its trim threshold to twice
// that: once a few images had been freed, every thread's heap kept megabytes of free space at its
// top, and a SLAM run's RSS crept up for minutes. Fixed thresholds keep blocks up to 32 MB in
// the heaps (no page faults for every image, as a low mmap threshold would cost) and give free
// space beyond 512 kB at a heap's top back to the system. Call once, before threads start.
// Returns false where malloc is not glibc's (another C library, a sanitizer's allocator) or it
// refused a setting.
bool boundHeapRetention();

// Gives the free pages inside every thread's heap back to the system (glibc's malloc_trim) every
// `interval`, on a thread of its own, for as long as it lives. The trim threshold only reaches
// a heap's top: images and solver blocks freed below a block still in use stayed resident, 15-25
// MB across the heaps of a SLAM run, and the sum crept up as rarer peaks of images in flight came
// (static 9-sweep soak: 14 MB after the first sweep). A trim takes ~5 ms; a page given back costs
// a fault when reused, so trims are a second apart rather than after every frame. Does nothing
// (active() false) where malloc is not glibc's.
class HeapTrimmer {
 public:
  explicit HeapTrimmer(std::chrono::milliseconds interval = std::chrono::seconds(1));
  ~HeapTrimmer();
  HeapTrimmer(const HeapTrimmer&) = delete;
  HeapTrimmer& operator=(const HeapTrimmer&) = delete;

  [[nodiscard]] bool active() const { return thread_.joinable(); }
  [[nodiscard]] std::size_t trims();

 private:
  void run(std::chrono::milliseconds interval);

  std::mutex mutex_;
  std::condition_variable stop_requested_;
  bool stopping_ = false;
  std::size_t trims_ = 0;
  std::thread thread_;
};

// Gives the free pages inside every heap back to the system now; false where malloc is not
// glibc's.
bool trimHeaps();

}  // namespace segslam::util
