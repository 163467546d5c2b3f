#include "segslam/synth/sequence.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "segslam/util/error.h"

namespace segslam::synth {
namespace {

TEST(SynthSequence, RendersAnyFrameReproduciblyWithItsGroundTruth) {
  SynthOptions options;
  options.frames = 20;
  options.width = 80;
  options.height = 60;
  options.depth_noise = "kinect";
  const SyntheticSequence sequence(options);
  EXPECT_EQ(sequence.frameCount(), 20);
  EXPECT_EQ(sequence.cameraPoses().size(), 20u);
  EXPECT_EQ(sequence.camera().width, 80);
  EXPECT_DOUBLE_EQ(sequence.timestamp(3), frameTimestamp(3));
  const FrameImages late = sequence.renderFrame(17);
  const FrameImages early = sequence.renderFrame(2);
  const FrameImages again = sequence.renderFrame(17);
  EXPECT_EQ(cv::norm(late.rgb, again.rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(late.depth, again.depth, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(late.rgb, early.rgb, cv::NORM_L1), 0.0);
  // Every pixel sees something in the closed room, and people are in view.
  EXPECT_EQ(cv::countNonZero(late.instances), 80 * 60);
  EXPECT_GT(cv::countNonZero(late.mask), 0);
  EXPECT_THROW((void)sequence.renderFrame(20), std::out_of_range);
  EXPECT_THROW((void)sequence.renderFrame(-1), std::out_of_range);
}

TEST(SynthSequence, RejectsInvalidOptions) {
  SynthOptions options;
  options.path = "circle";
  EXPECT_THROW(SyntheticSequence{options}, util::Error);
}

}  // namespace
}  // namespace segslam::synth
