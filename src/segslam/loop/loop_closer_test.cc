#include "segslam/loop/loop_closer.h"

#include <gtest/gtest.h>

#include "segslam/io/tum_dataset.h"
#include "segslam/synth/generator.h"
#include "segslam/system/sequence_runner.h"
#include "segslam/testing/test_support.h"

// End to end: a synthetic lap through a room that ends where it started, tracked with few
// features and Kinect-like depth noise so that the odometry drifts; closing the loop must remove
// most of the drift, and the accepted loops must agree with the ground truth.
namespace segslam::loop {
namespace {

using testing::ScopedTempDir;

// Few features per frame: the odometry drifts by centimetres over the lap.
constexpr int kLapFeatures = 400;

system::SequenceRunSummary runLap(const std::filesystem::path& dataset, bool loop_closing,
                                  const std::filesystem::path& out_dir) {
  system::SequenceRunOptions options;
  options.slam.deterministic = true;
  options.slam.loop_closing = loop_closing;
  options.slam.orb.num_features = kLapFeatures;
  return system::runSequence(io::TumDataset::open(dataset), options, out_dir,
                             [](const system::FrameStats&) {});
}

TEST(LoopCloser, ClosingTheLapRemovesMostOfTheDrift) {
  const ScopedTempDir dir;
  synth::SynthOptions lap;
  lap.path = "loop";
  lap.people = 0;
  lap.frames = 300;
  lap.width = 320;
  lap.height = 240;
  lap.depth_noise = "kinect";
  lap.seed = 1;
  synth::generateSequence(lap, dir.path() / "lap");
  const auto open_loop = runLap(dir.path() / "lap", false, dir.path() / "off");
  const auto closed = runLap(dir.path() / "lap", true, dir.path() / "on");
  ASSERT_TRUE(open_loop.evaluation && closed.evaluation);
  const double ate_off = open_loop.evaluation->ate.statistics.rmse;
  const double ate_on = closed.evaluation->ate.statistics.rmse;
  EXPECT_GE(closed.loops.loops_accepted, 1);
  EXPECT_LT(ate_on, 0.5 * ate_off)
      << "ATE " << ate_on << " m with loop closing, " << ate_off << " m without";
  ASSERT_EQ(closed.loop_checks.size(), closed.loops.loops.size());
  for (const auto& check : closed.loop_checks) {
    ASSERT_TRUE(check.has_value());
    EXPECT_LT(check->translation_error_m, 0.05);
    EXPECT_LT(check->rotation_error_deg, 2.0);
  }
}

}  // namespace
}  // namespace segslam::loop
