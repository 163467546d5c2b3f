#include "segslam/segmentation/semantic_segmenter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "segslam/feature/orb_extractor.h"
#include "segslam/feature/static_mask.h"
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

struct RealPersonFrame {
  cv::Mat bgr;
  cv::Mat person_area;  // CV_8UC1, 255 = the dataset's person area (coarse, dilated)
};

RealPersonFrame loadRealPersonFrame(const std::filesystem::path& frames, const std::string& stamp) {
  const cv::Mat bgr = cv::imread((frames / "rgb" / (stamp + ".png")).string());
  const cv::Mat truth =
      cv::imread((frames / "mask" / (stamp + ".png")).string(), cv::IMREAD_GRAYSCALE);
  return {bgr, truth.empty() ? cv::Mat() : cv::Mat(truth == 0)};
}

struct PersonCover {
  double covered = 0.0;      // share of the person area marked
  double false_marks = 0.0;  // share of the rest marked
};

PersonCover personCover(const cv::Mat& dynamic, const cv::Mat& person_area) {
  const double person_pixels = cv::countNonZero(person_area);
  const double rest_pixels = static_cast<double>(person_area.total()) - person_pixels;
  return {cv::countNonZero(dynamic & person_area) / person_pixels,
          cv::countNonZero(dynamic & ~person_area) / rest_pixels};
}

SemanticSegmenter espnetSegmenter() {
  const auto models = *testing::sharedDir() / "models";
  return SemanticSegmenter(readModelConfig(espnetConfigFile()), models / "espnetv2_voc_384.onnx");
}

// The two real TUM walking_xyz frames: the predicted person pixels must cover their masks
// (0 = person area, coarse and dilated) and mark little else. The raw network output reaches 81 %
// and 73 %. In the second frame the dataset has erased the people (colour 0,0,0 and depth 0 on
// every pixel of the person area): the network still finds most of the black silhouettes but
// not the legs, so this guards the raw figure of both frames.
TEST(SemanticSegmenter, FindsThePeopleInRealTumFrames) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  SemanticSegmenter segmenter = espnetSegmenter();
  for (const char* stamp : {"1341846313.592026", "1341846316.570121"}) {
    const RealPersonFrame frame = loadRealPersonFrame(frames, stamp);
    ASSERT_FALSE(frame.bgr.empty()) << stamp;
    ASSERT_FALSE(frame.person_area.empty()) << stamp;
    const SemanticMasks masks = segmenter.segment(frame.bgr);
    ASSERT_EQ(masks.labels.size(), frame.bgr.size());
    const PersonCover cover = personCover(masks.dynamic, frame.person_area);
    EXPECT_GE(cover.covered, 0.70) << stamp;
    EXPECT_LT(cover.false_marks, 0.05) << stamp;
    EXPECT_EQ(cv::countNonZero(masks.dynamic != (masks.labels == 15)), 0);
  }
}

// The warm-up pass over a blank image leaves no trace: a warmed network labels a frame exactly as
// a fresh one does.
TEST(SemanticSegmenter, WarmUpDoesNotChangeTheLabels) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  const RealPersonFrame frame = loadRealPersonFrame(frames, "1341846313.592026");
  ASSERT_FALSE(frame.bgr.empty());
  SemanticSegmenter fresh = espnetSegmenter();
  SemanticSegmenter warmed = espnetSegmenter();
  warmed.warmUp();
  EXPECT_EQ(cv::countNonZero(fresh.segment(frame.bgr).labels != warmed.segment(frame.bgr).labels),
            0);
}

// The segmentation issue's target (at least 90 % of the person area, under 5 % of the rest) on
// the frame whose people are intact (one seated, one standing), with the mask as SLAM uses it:
// dilated by the extractor's margin, as the dataset's person area is dilated too.
TEST(SemanticSegmenter, MaskAsSlamUsesItCoversTheIntactRealPeople) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  SemanticSegmenter segmenter = espnetSegmenter();
  const RealPersonFrame frame = loadRealPersonFrame(frames, "1341846313.592026");
  ASSERT_FALSE(frame.bgr.empty());
  ASSERT_FALSE(frame.person_area.empty());
  const cv::Mat dilated = feature::dilateDynamicMask(
      segmenter.segment(frame.bgr).dynamic, feature::OrbExtractorOptions{}.mask_dilation_px);
  const PersonCover cover = personCover(dilated, frame.person_area);
  EXPECT_GE(cover.covered, 0.90);
  EXPECT_LT(cover.false_marks, 0.05);
}

}  // namespace
}  // namespace segslam::segmentation
