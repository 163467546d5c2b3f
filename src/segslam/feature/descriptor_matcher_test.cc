#include "segslam/feature/descriptor_matcher.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>

#include "segslam/feature/descriptor_distance.h"

namespace segslam::feature {
namespace {

// Row `row` of `descriptors` becomes all zeros except the first `bits` bits set.
void setBits(cv::Mat& descriptors, int row, int bits) {
  descriptors.row(row).setTo(0);
  for (int bit = 0; bit < bits; ++bit) {
    descriptors.at<std::uint8_t>(row, bit / 8) |= static_cast<std::uint8_t>(1 << (bit % 8));
  }
}

TEST(FeatureMatcher, FindsNearestAndAppliesRatioAndDistance) {
  cv::Mat train(3, kDescriptorBytes, CV_8UC1);
  setBits(train, 0, 0);
  setBits(train, 1, 40);
  setBits(train, 2, 200);
  cv::Mat query(4, kDescriptorBytes, CV_8UC1);
  setBits(query, 0, 2);    // 2 from row 0, 38 from row 1: clear
  setBits(query, 1, 39);   // 39 from row 0, 1 from row 1: clear
  setBits(query, 2, 20);   // 20 from row 0, 20 from row 1: ambiguous, fails the ratio test
  setBits(query, 3, 120);  // nearest is row 1 at 80 bits: too far
  DescriptorMatcherOptions options;
  options.max_distance = 64;
  options.ratio = 0.8;
  const auto matches = matchDescriptors(query, train, options);
  ASSERT_EQ(matches.size(), 2u);
  EXPECT_EQ(matches[0].queryIdx, 0);
  EXPECT_EQ(matches[0].trainIdx, 0);
  EXPECT_FLOAT_EQ(matches[0].distance, 2.0f);
  EXPECT_EQ(matches[1].queryIdx, 1);
  EXPECT_EQ(matches[1].trainIdx, 1);
  EXPECT_FLOAT_EQ(matches[1].distance, 1.0f);

  options.ratio = 1.0;  // no ratio test: the tie goes to the first train row
  options.max_distance = 256;
  const auto all = matchDescriptors(query, train, options);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[2].trainIdx, 0);
  EXPECT_EQ(all[3].trainIdx, 1);
}

TEST(FeatureMatcher, SingleTrainRowAndEmptyInputs) {
  cv::Mat train(1, kDescriptorBytes, CV_8UC1, cv::Scalar(0));
  cv::Mat query(1, kDescriptorBytes, CV_8UC1, cv::Scalar(0));
  EXPECT_EQ(matchDescriptors(query, train).size(), 1u);
  EXPECT_TRUE(matchDescriptors(cv::Mat(), train).empty());
  EXPECT_TRUE(matchDescriptors(query, cv::Mat()).empty());
}

TEST(FeatureMatcher, RejectsWrongLayout) {
  const cv::Mat good(2, kDescriptorBytes, CV_8UC1, cv::Scalar(0));
  EXPECT_THROW(matchDescriptors(cv::Mat(2, 16, CV_8UC1, cv::Scalar(0)), good),
               std::invalid_argument);
  EXPECT_THROW(matchDescriptors(good, cv::Mat(2, kDescriptorBytes, CV_32FC1, cv::Scalar(0))),
               std::invalid_argument);
}

}  // namespace
}  // namespace segslam::feature
