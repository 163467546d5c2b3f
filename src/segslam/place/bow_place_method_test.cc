#include "segslam/place/bow_place_method.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <opencv2/imgproc.hpp>

#include "segslam/feature/feature_test_images.h"
#include "segslam/feature/orb_extractor.h"

namespace segslam::place {
namespace {

cv::Mat toBgr(const cv::Mat& gray) {
  cv::Mat bgr;
  cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

// Few shapes and a feature budget above the number of corners: the extractor then keeps every
// corner, so that what it finds away from a change does not depend on the change.
constexpr int kShapes = 200;

feature::OrbExtractorOptions testOrbOptions() {
  feature::OrbExtractorOptions options;
  options.num_features = 20000;
  options.num_levels = 4;
  return options;
}

// Two scenes that differ only inside `changed`, and a vocabulary trained on them and others.
class BowPlaceMethodTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = feature::testing::texturedImage(size_, 5, kShapes);
    changed_scene_ = scene_.clone();
    feature::testing::texturedImage(changed_.size(), 6, kShapes).copyTo(changed_scene_(changed_));
    // Unrelated scenes too: words in every training image would get an IDF weight of 0.
    std::vector<cv::Mat> training{scene_, changed_scene_};
    for (std::uint64_t seed = 10; seed < 22; ++seed) {
      training.push_back(feature::testing::texturedImage(size_, seed, kShapes));
    }
    feature::OrbExtractor extractor(testOrbOptions());
    std::vector<cv::Mat> sets;
    for (const cv::Mat& image : training) {
      std::vector<cv::KeyPoint> keypoints;
      cv::Mat descriptors;
      extractor.extract(image, cv::Mat(), keypoints, descriptors);
      sets.push_back(descriptors);
    }
    VocabularyOptions options;
    options.k = 10;
    options.depth = 4;
    vocabulary_ = std::make_shared<Vocabulary>(Vocabulary::train(sets, options));
  }

  const cv::Size size_{480, 360};
  // The change, and the masked area around it: a margin wider than the ORB patch and FAST cell at
  // the top pyramid level, so that no keypoint outside the mask sees the change.
  const cv::Rect changed_{200, 140, 80, 80};
  const cv::Rect masked_{110, 50, 260, 260};
  cv::Mat scene_;
  cv::Mat changed_scene_;
  std::shared_ptr<const Vocabulary> vocabulary_;
};

TEST_F(BowPlaceMethodTest, SameImageScoresOne) {
  BowPlaceMethod method(vocabulary_, testOrbOptions());
  EXPECT_EQ(method.name(), "bow");
  method.add({toBgr(scene_), {}});
  method.add({toBgr(scene_), {}});
  ASSERT_EQ(method.size(), 2U);
  EXPECT_DOUBLE_EQ(method.similarity(0, 1, false), 1.0);
  EXPECT_DOUBLE_EQ(method.similarity(0, 1, true), 1.0);
}

TEST_F(BowPlaceMethodTest, UnionMaskIgnoresKeypointsInTheMaskedArea) {
  BowPlaceMethod method(vocabulary_, testOrbOptions());
  cv::Mat static_mask(size_, CV_8UC1, cv::Scalar(255));
  static_mask(masked_).setTo(0);
  method.add({toBgr(scene_), {}});
  // Only the changed image says where its moving object is; the union applies it to both.
  method.add({toBgr(changed_scene_), static_mask});
  const double without_mask = method.similarity(0, 1, false);
  const double with_mask = method.similarity(0, 1, true);
  EXPECT_LT(without_mask, 0.95);
  EXPECT_NEAR(with_mask, 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(method.similarity(1, 0, true), with_mask);
}

TEST_F(BowPlaceMethodTest, StaticVariantDescribesEachImageByItsOwnStaticArea) {
  BowPlaceMethod method(vocabulary_, testOrbOptions(), BowMasking::kOwnStaticArea);
  EXPECT_EQ(method.name(), "bow:static");
  cv::Mat static_mask(size_, CV_8UC1, cv::Scalar(255));
  static_mask(masked_).setTo(0);
  method.add({toBgr(scene_), static_mask});
  method.add({toBgr(changed_scene_), static_mask});
  EXPECT_LT(method.similarity(0, 1, false), 0.95);
  EXPECT_NEAR(method.similarity(0, 1, true), 1.0, 1e-9);
}

TEST_F(BowPlaceMethodTest, StaticVariantKeepsWordsUnderTheOtherImagesMask) {
  cv::Mat static_mask(size_, CV_8UC1, cv::Scalar(255));
  static_mask(masked_).setTo(0);
  BowPlaceMethod union_method(vocabulary_, testOrbOptions());
  BowPlaceMethod static_method(vocabulary_, testOrbOptions(), BowMasking::kOwnStaticArea);
  for (PlaceDescriptorMethod* method :
       std::initializer_list<PlaceDescriptorMethod*>{&union_method, &static_method}) {
    method->add({toBgr(scene_), {}});
    method->add({toBgr(scene_), static_mask});
  }
  // The union drops the unmasked image's words in the other's masked area; the static variant
  // keeps them, so the unmasked image has words the masked one lacks.
  EXPECT_NEAR(union_method.similarity(0, 1, true), 1.0, 1e-9);
  EXPECT_LT(static_method.similarity(0, 1, true), 0.9);
  EXPECT_DOUBLE_EQ(static_method.similarity(0, 1, false), 1.0);
}

TEST_F(BowPlaceMethodTest, RejectsBadImages) {
  BowPlaceMethod method(vocabulary_, testOrbOptions());
  EXPECT_THROW(method.add({cv::Mat(), {}}), std::invalid_argument);
  EXPECT_THROW(method.add({toBgr(scene_), cv::Mat(10, 10, CV_8UC1)}), std::invalid_argument);
  EXPECT_THROW((void)method.similarity(0, 0, false), std::out_of_range);
}

}  // namespace
}  // namespace segslam::place
