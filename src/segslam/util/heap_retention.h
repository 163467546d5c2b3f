#pragma once

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

}  // namespace segslam::util
