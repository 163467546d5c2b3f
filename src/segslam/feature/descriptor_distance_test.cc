#include "segslam/feature/descriptor_distance.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace segslam::feature {
namespace {

using Descriptor = std::array<std::uint8_t, kDescriptorBytes>;

TEST(FeatureDescriptorDistance, CountsDifferingBits) {
  Descriptor a{};
  Descriptor b{};
  EXPECT_EQ(descriptorDistance(a.data(), b.data()), 0);
  b[0] = 0b0000'0001;
  EXPECT_EQ(descriptorDistance(a.data(), b.data()), 1);
  b[7] = 0xFF;   // last byte of the first 64-bit word
  b[8] = 0x80;   // first byte of the second
  b[31] = 0x0F;  // last byte
  EXPECT_EQ(descriptorDistance(a.data(), b.data()), 1 + 8 + 1 + 4);
  EXPECT_EQ(descriptorDistance(b.data(), a.data()), 14);
  a.fill(0xFF);
  b.fill(0x00);
  EXPECT_EQ(descriptorDistance(a.data(), b.data()), kDescriptorBits);
}

TEST(FeatureDescriptorDistance, Popcount) {
  EXPECT_EQ(popcount64(0), 0);
  EXPECT_EQ(popcount64(~std::uint64_t{0}), 64);
  EXPECT_EQ(popcount64(0x8000000000000001ULL), 2);
  EXPECT_EQ(popcount64(0x0123456789ABCDEFULL), 32);
}

TEST(FeatureDescriptorDistance, WorksOnUnalignedDataAndMatRows) {
  std::array<std::uint8_t, 2 * kDescriptorBytes + 1> buffer{};
  buffer[1] = 0xAA;                     // 4 bits, first descriptor starts at an odd address
  buffer[1 + kDescriptorBytes] = 0x55;  // 4 other bits in the second
  EXPECT_EQ(descriptorDistance(buffer.data() + 1, buffer.data() + 1 + kDescriptorBytes), 8);

  cv::Mat rows(2, kDescriptorBytes, CV_8UC1, cv::Scalar(0));
  rows.at<std::uint8_t>(1, 5) = 0b1011;
  EXPECT_EQ(descriptorDistance(rows.row(0), rows.row(1)), 3);
}

}  // namespace
}  // namespace segslam::feature
