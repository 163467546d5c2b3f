#include "segslam/segmentation/semantic_mask_stream.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "segslam/testing/test_support.h"

namespace segslam::segmentation {
namespace {

SemanticSegmenter espnet() {
  const auto config_file =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";
  return SemanticSegmenter(readModelConfig(config_file),
                           *testing::sharedDir() / "models" / "espnetv2_voc_384.onnx");
}

TEST(SemanticMaskStream, EveryFrameGetsAMaskWithoutWaitingForTheNetwork) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  const cv::Mat bgr = cv::imread((frames / "rgb" / "1341846313.592026.png").string());
  ASSERT_FALSE(bgr.empty());
  SemanticSegmenter direct = espnet();
  const SemanticMasks expected = direct.segment(bgr);
  const MaskStreamOptions options;
  cv::Mat grown_limit;
  const int limit = options.max_growth_px + 1;
  cv::dilate(expected.dynamic, grown_limit,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * limit + 1, 2 * limit + 1)));
  SemanticMaskStream stream(espnet(), options);
  for (std::uint64_t frame = 0; frame < 12; ++frame) {
    const SemanticMasks masks = stream.masksFor(frame, bgr);
    ASSERT_EQ(masks.dynamic.size(), bgr.size()) << frame;
    ASSERT_EQ(masks.labels.size(), bgr.size()) << frame;
    // The camera does not move, so whichever output the frame gets, it covers the first
    // frame's, grown by at most the options' limit as it ages.
    EXPECT_LT(cv::countNonZero(expected.dynamic & ~masks.dynamic), 0.01 * bgr.total()) << frame;
    EXPECT_EQ(cv::countNonZero(masks.dynamic & ~grown_limit), 0) << frame;
  }
  // The first frame waits for its own output; later frames only take what is finished.
  EXPECT_GE(stream.networkRuns(), 1);
  EXPECT_LT(stream.networkRuns(), 12);
}

TEST(SemanticMaskStream, SynchronousModeRunsTheNetworkEveryIntervalFrames) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  const cv::Mat bgr = cv::imread((frames / "rgb" / "1341846316.570121.png").string());
  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = 4;
  SemanticMaskStream stream(espnet(), options);
  for (std::uint64_t frame = 0; frame < 9; ++frame) {
    EXPECT_GT(cv::countNonZero(stream.masksFor(frame, bgr).dynamic), 0) << frame;
  }
  EXPECT_EQ(stream.networkRuns(), 3);  // frames 0, 4 and 8
}

}  // namespace
}  // namespace segslam::segmentation
