#include "segslam/place/masked_similarity.h"

#include <gtest/gtest.h>

namespace segslam::place {
namespace {

TEST(MaskedSimilarity, UnionMaskCosineEqualsCosineOfMaskedMaps) {
  // Two channels on a 2 x 2 grid; the union mask keeps cell 0 fully and cell 1 half.
  const cv::Mat a = (cv::Mat_<float>(2, 4) << 1, 2, 3, 4, 5, 6, 7, 8);
  const cv::Mat b = (cv::Mat_<float>(2, 4) << 2, 1, 0, 9, 1, 1, 4, 2);
  const cv::Mat weights = (cv::Mat_<float>(1, 4) << 1, 0.5, 0, 0);
  const cv::Mat masked_a = (cv::Mat_<float>(2, 4) << 1, 1, 0, 0, 5, 3, 0, 0);
  const cv::Mat masked_b = (cv::Mat_<float>(2, 4) << 2, 0.5, 0, 0, 1, 0.5, 0, 0);
  const double expected = masked_a.dot(masked_b) / (cv::norm(masked_a) * cv::norm(masked_b));
  EXPECT_NEAR(maskedCosine(a, b, weights), expected, 1e-12);
  EXPECT_NEAR(maskedCosine(a, a, weights), 1.0, 1e-12);
}

TEST(MaskedSimilarity, CosineOfZeroVectorsIsZero) {
  const cv::Mat zero(2, 3, CV_32F, cv::Scalar(0));
  const cv::Mat ones(2, 3, CV_32F, cv::Scalar(1));
  EXPECT_EQ(cosineSimilarity(zero, ones), 0.0);
  EXPECT_NEAR(cosineSimilarity(ones, ones), 1.0, 1e-12);
}

TEST(MaskedSimilarity, PooledIgnoresDifferencesUnderTheMask) {
  // One channel on a 4 x 2 grid pooled into 2 x 1 cells. The maps differ only in grid cell 1
  // (top row), which the mask removes: the remaining cell means are identical.
  const cv::Mat a = (cv::Mat_<float>(1, 8) << 1, 2, 3, 4, 5, 6, 7, 8);
  cv::Mat b = a.clone();
  b.at<float>(1) = 100.0f;
  const cv::Mat weights = (cv::Mat_<float>(1, 8) << 1, 0, 1, 1, 1, 1, 1, 1);
  EXPECT_NEAR(pooledMaskedCosine(a, b, weights, {4, 2}, {2, 1}), 1.0, 1e-6);
  // Without the mask the difference counts.
  const cv::Mat all(1, 8, CV_32F, cv::Scalar(1));
  EXPECT_LT(pooledMaskedCosine(a, b, all, {4, 2}, {2, 1}), 0.99);
}

TEST(MaskedSimilarity, PooledMeansAreNormalisedByStaticArea) {
  // b is twice a wherever the mask is static, anything elsewhere.
  const cv::Mat a = (cv::Mat_<float>(1, 4) << 1, 3, 5, 7);
  const cv::Mat b = (cv::Mat_<float>(1, 4) << 2, 0, 10, 14);
  const cv::Mat weights = (cv::Mat_<float>(1, 4) << 1, 0, 1, 1);
  // The left pooling cell holds grid cells 0 and 2, the right one 1 and 3 (only 3 static):
  // a's means are (3, 7), b's (6, 14): parallel, although b's right cell has a 0 under the mask.
  EXPECT_NEAR(pooledMaskedCosine(a, b, weights, {2, 2}, {2, 1}), 1.0, 1e-6);
}

TEST(MaskedSimilarity, PooledWithNothingStaticIsZero) {
  const cv::Mat a(1, 4, CV_32F, cv::Scalar(1));
  const cv::Mat none(1, 4, CV_32F, cv::Scalar(0));
  EXPECT_EQ(pooledMaskedCosine(a, a, none, {2, 2}, {2, 1}), 0.0);
}

TEST(MaskedSimilarity, OwnMaskPoolingAveragesEachMapOverItsOwnStaticArea) {
  // One channel on a 4 x 2 grid pooled into 2 x 1 cells; the background is 1 in the left half
  // and 3 in the right one. a shows a mover in grid cell 1 (its own mask), b in grid cell 2.
  const cv::Mat a = (cv::Mat_<float>(1, 8) << 1, 50, 3, 3, 1, 1, 3, 3);
  const cv::Mat b = (cv::Mat_<float>(1, 8) << 1, 1, 90, 3, 1, 1, 3, 3);
  const cv::Mat own_a = (cv::Mat_<float>(1, 8) << 1, 0, 1, 1, 1, 1, 1, 1);
  const cv::Mat own_b = (cv::Mat_<float>(1, 8) << 1, 1, 0, 1, 1, 1, 1, 1);
  EXPECT_NEAR(pooledOwnMaskCosine(a, b, own_a, own_b, {4, 2}, {2, 1}), 1.0, 1e-6);
  const cv::Mat all(1, 8, CV_32F, cv::Scalar(1));
  EXPECT_LT(pooledOwnMaskCosine(a, b, all, all, {4, 2}, {2, 1}), 0.99);
}

TEST(MaskedSimilarity, OwnMaskPoolingLeavesOutCellsEitherImageCannotSee) {
  // a's left pooling cell is all dynamic: that cell is left out of both, whatever b shows there.
  const cv::Mat a = (cv::Mat_<float>(1, 8) << 7, 7, 3, 3, 7, 7, 3, 3);
  const cv::Mat b = (cv::Mat_<float>(1, 8) << 1, 2, 3, 3, 4, 5, 3, 3);
  const cv::Mat own_a = (cv::Mat_<float>(1, 8) << 0, 0, 1, 1, 0, 0, 1, 1);
  const cv::Mat own_b(1, 8, CV_32F, cv::Scalar(1));
  EXPECT_NEAR(pooledOwnMaskCosine(a, b, own_a, own_b, {4, 2}, {2, 1}), 1.0, 1e-6);
  const cv::Mat none(1, 8, CV_32F, cv::Scalar(0));
  EXPECT_EQ(pooledOwnMaskCosine(a, b, none, own_b, {4, 2}, {2, 1}), 0.0);
}

}  // namespace
}  // namespace segslam::place
