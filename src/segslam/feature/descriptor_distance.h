#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>

namespace segslam::feature {

// ORB descriptors are 256 binary tests packed into 32 bytes (one row of an N x 32 CV_8U Mat).
inline constexpr int kDescriptorBytes = 32;
inline constexpr int kDescriptorBits = 8 * kDescriptorBytes;

// Bits set in a 64-bit word. Without the POPCNT instruction (baseline x86-64, as this project is
// built) std::popcount is a libgcc call, four times slower than this inline bit-slicing count.
inline int popcount64(std::uint64_t word) {
#if defined(__x86_64__) && !defined(__POPCNT__)
  word -= (word >> 1) & 0x5555555555555555ULL;
  word = (word & 0x3333333333333333ULL) + ((word >> 2) & 0x3333333333333333ULL);
  word = (word + (word >> 4)) & 0x0F0F0F0F0F0F0F0FULL;
  return static_cast<int>((word * 0x0101010101010101ULL) >> 56);
#else
  return std::popcount(word);
#endif
}

// Hamming distance of two 256-bit descriptors (0..256): popcount of their XOR, 64 bits at a time.
// memcpy keeps the 64-bit loads legal for any alignment; compilers turn it into plain loads.
inline int descriptorDistance(const std::uint8_t* a, const std::uint8_t* b) {
  int distance = 0;
  for (int offset = 0; offset < kDescriptorBytes; offset += 8) {
    std::uint64_t word_a = 0;
    std::uint64_t word_b = 0;
    std::memcpy(&word_a, a + offset, sizeof word_a);
    std::memcpy(&word_b, b + offset, sizeof word_b);
    distance += popcount64(word_a ^ word_b);
  }
  return distance;
}

// Same on two descriptor rows (1 x 32 CV_8U, e.g. descriptors.row(i)).
inline int descriptorDistance(const cv::Mat& a, const cv::Mat& b) {
  CV_DbgAssert(a.type() == CV_8UC1 && b.type() == CV_8UC1 && a.total() == kDescriptorBytes &&
               b.total() == kDescriptorBytes);
  return descriptorDistance(a.ptr<std::uint8_t>(), b.ptr<std::uint8_t>());
}

}  // namespace segslam::feature
