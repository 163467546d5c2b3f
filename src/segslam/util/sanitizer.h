#pragma once

// SEGSLAM_ADDRESS_SANITIZER is defined where the code is built with AddressSanitizer, whose
// allocator then stands in for the C library's. GCC says so with __SANITIZE_ADDRESS__, clang
// (before 16) only through __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define SEGSLAM_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SEGSLAM_ADDRESS_SANITIZER 1
#endif
#endif
