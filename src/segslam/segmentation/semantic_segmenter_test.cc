#include "segslam/segmentation/semantic_segmenter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::segmentation {
namespace {

using testing::ScopedTempDir;

std::filesystem::path espnetConfigFile() {
  return std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";
}

TEST(SemanticSegmenter, CorruptModelFileIsAnErrorNamingIt) {
  const ScopedTempDir dir;
  const auto model = dir.path() / "broken.onnx";
  std::ofstream(model) << "not a network";
  EXPECT_THROW(SemanticSegmenter(readModelConfig(espnetConfigFile()), model), util::Error);
}

// The two real TUM walking_xyz frames: the predicted person pixels must cover their masks
// (0 = person area, coarse and dilated) and mark little else. The segmentation issue's target is
// 90 % coverage; the raw network output reaches 81 % and 73 % (it misses legs), so this guards the
// current figure until mask post-processing closes the gap.
TEST(SemanticSegmenter, FindsThePeopleInRealTumFrames) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  const auto models = *testing::sharedDir() / "models";
  const ModelConfig config = readModelConfig(espnetConfigFile());
  SemanticSegmenter segmenter(config, models / "espnetv2_voc_384.onnx");
  for (const char* stamp : {"1341846313.592026", "1341846316.570121"}) {
    const cv::Mat bgr = cv::imread((frames / "rgb" / (std::string(stamp) + ".png")).string());
    const cv::Mat truth = cv::imread((frames / "mask" / (std::string(stamp) + ".png")).string(),
                                     cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(bgr.empty());
    ASSERT_FALSE(truth.empty());
    const SemanticMasks masks = segmenter.segment(bgr);
    ASSERT_EQ(masks.labels.size(), bgr.size());
    const cv::Mat person_area = truth == 0;
    const double person_pixels = cv::countNonZero(person_area);
    const double rest_pixels = person_area.total() - person_pixels;
    const double covered = cv::countNonZero(masks.dynamic & person_area) / person_pixels;
    const double false_marks = cv::countNonZero(masks.dynamic & ~person_area) / rest_pixels;
    EXPECT_GE(covered, 0.70) << stamp;
    EXPECT_LT(false_marks, 0.05) << stamp;
    EXPECT_EQ(cv::countNonZero(masks.dynamic != (masks.labels == 15)), 0);
  }
}

}  // namespace
}  // namespace segslam::segmentation
