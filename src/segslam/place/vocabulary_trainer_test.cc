#include "segslam/place/vocabulary_trainer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "segslam/feature/feature_test_images.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::place {
namespace {

TEST(VocabularyTrainerTest, TakesEveryNthImageOfAFolderInNameOrder) {
  segslam::testing::ScopedTempDir dir;
  for (int i = 0; i < 5; ++i) {
    cv::imwrite((dir.path() / ("image_" + std::to_string(i) + ".png")).string(),
                feature::testing::texturedImage({160, 120}, static_cast<std::uint64_t>(i), 100));
  }
  std::ofstream(dir.path() / "notes.txt") << "not an image";
  const auto images = listTrainingImages({{TrainingSource::Kind::kImageFolder, dir.path()}}, 2);
  ASSERT_EQ(images.size(), 3U);
  EXPECT_EQ(images[0].image.filename(), "image_0.png");
  EXPECT_EQ(images[1].image.filename(), "image_2.png");
  EXPECT_EQ(images[2].image.filename(), "image_4.png");
  EXPECT_FALSE(images[0].dynamic_mask.has_value());

  feature::OrbExtractorOptions orb;
  orb.num_features = 200;
  int progress = 0;
  const auto sets = extractTrainingDescriptors(images, orb, [&] { ++progress; });
  ASSERT_EQ(sets.size(), 3U);
  EXPECT_EQ(progress, 3);
  EXPECT_GT(sets[0].rows, 50);
  EXPECT_EQ(sets[0].cols, 32);
}

TEST(VocabularyTrainerTest, FolderWithoutImagesIsAnError) {
  segslam::testing::ScopedTempDir dir;
  try {
    (void)listTrainingImages({{TrainingSource::Kind::kImageFolder, dir.path()}}, 1);
    FAIL() << "no error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.path().string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      (void)listTrainingImages({{TrainingSource::Kind::kImageFolder, dir.path() / "absent"}}, 1),
      util::Error);
}

TEST(VocabularyTrainerTest, UndecodableImageIsAnError) {
  segslam::testing::ScopedTempDir dir;
  std::ofstream(dir.path() / "broken.png") << "not a png";
  const auto images = listTrainingImages({{TrainingSource::Kind::kImageFolder, dir.path()}}, 1);
  EXPECT_THROW((void)extractTrainingDescriptors(images, {}), util::Error);
}

TEST(VocabularyTrainerTest, ReadsTumSequencesWithTheirMasks) {
  SEGSLAM_REQUIRE_SHARED(walker, "tum_fr1_xyz_300_walker");
  const auto images = listTrainingImages({{TrainingSource::Kind::kTumDataset, walker}}, 100);
  ASSERT_EQ(images.size(), 3U);
  EXPECT_TRUE(images[0].dynamic_mask.has_value());
}

}  // namespace
}  // namespace segslam::place
