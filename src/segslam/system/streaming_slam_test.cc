#include "segslam/system/streaming_slam.h"

#include <gtest/gtest.h>

#include "segslam/system/sequence_runner.h"
#include "segslam/testing/synth_sequences.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::system {
namespace {

using testing::ScopedTempDir;

// A short synthetic sequence with one walking person, rendered once for the suite.
io::TumDataset syntheticDataset() {
  synth::SynthOptions options;
  options.frames = 40;
  options.people = 1;
  options.seed = 1;
  return io::TumDataset::open(testing::sharedSequence(options));
}

StreamingSlamOptions deterministicOptions(MaskSource masks) {
  StreamingSlamOptions options;
  options.slam.deterministic = true;
  options.masks.source = masks;
  return options;
}

// Oracle masks are the caller's: the dataset's ground-truth masks handed over with each frame.
core::Trajectory streamDataset(const io::TumDataset& dataset, StreamingSlam& slam,
                               bool with_masks) {
  for (std::size_t i = 0; i < dataset.size(); ++i) {
    const auto frame = dataset.loadFrame(i, {with_masks, false, false});
    const StreamedFrame streamed = slam.track(frame);
    EXPECT_EQ(streamed.stats.frame_id, i);
    EXPECT_EQ(streamed.stats.T_wc.has_value(),
              streamed.stats.state == tracking::TrackingState::kOk);
  }
  slam.finish();
  return slam.cameraTrajectory();
}

// runSequence's trajectory as it was evaluated, before it was written at file precision.
core::Trajectory deterministicRun(const io::TumDataset& dataset, MaskSource masks,
                                  const std::filesystem::path& out_dir) {
  SequenceRunOptions options;
  options.slam.deterministic = true;
  options.masks.source = masks;
  const auto summary = runSequence(dataset, options, out_dir, [](const FrameStats&) {});
  return summary.evaluation ? summary.evaluation->estimate : core::Trajectory();
}

TEST(StreamingSlam, DeterministicStreamOfADatasetIsItsDeterministicRun) {
  const ScopedTempDir dir;
  const auto dataset = syntheticDataset();
  for (const MaskSource masks : {MaskSource::kGeometric, MaskSource::kOracle}) {
    SCOPED_TRACE(maskSourceName(masks));
    const auto run = deterministicRun(dataset, masks, dir.path() / maskSourceName(masks));
    StreamingSlam slam(dataset.camera(), deterministicOptions(masks));
    const auto streamed = streamDataset(dataset, slam, masks == MaskSource::kOracle);
    ASSERT_EQ(streamed.size(), run.size());
    EXPECT_GT(run.size(), dataset.size() / 2);
    for (std::size_t i = 0; i < run.size(); ++i) {
      EXPECT_EQ(streamed[i].timestamp, run[i].timestamp);
      EXPECT_TRUE(streamed[i].T_wc.isApprox(run[i].T_wc, 1e-12)) << "pose " << i;
    }
  }
}

TEST(StreamingSlam, CallersMaskIsAddedToTheSourcesAndNormalised) {
  const auto dataset = syntheticDataset();
  auto options = deterministicOptions(MaskSource::kNone);
  options.build_map = false;
  StreamingSlam slam(dataset.camera(), options);
  io::RgbdFrame frame = dataset.loadFrame(0, {false, false, false});
  frame.mask = cv::Mat::zeros(frame.rgb.size(), CV_8UC1);
  frame.mask(cv::Rect(0, 0, 10, 10)).setTo(1);
  const StreamedFrame streamed = slam.track(frame);
  EXPECT_EQ(cv::countNonZero(streamed.masks.dynamic), 100);
  EXPECT_EQ(streamed.masks.dynamic.at<std::uint8_t>(5, 5), 255);
}

TEST(StreamingSlam, NothingIsTrackedAfterFinishAndNoMapWithoutOne) {
  const auto dataset = syntheticDataset();
  auto options = deterministicOptions(MaskSource::kNone);
  options.build_map = false;
  StreamingSlam slam(dataset.camera(), options);
  const io::RgbdFrame frame = dataset.loadFrame(0, {false, false, false});
  slam.track(frame);
  slam.finish();
  EXPECT_TRUE(slam.finished());
  EXPECT_THROW(slam.track(dataset.loadFrame(1, {false, false, false})), util::Error);
  EXPECT_THROW((void)slam.denseMap(), util::Error);
}

TEST(StreamingSlam, DenseMapHoldsTheKeyFramesPoints) {
  const auto dataset = syntheticDataset();
  StreamingSlam slam(dataset.camera(), deterministicOptions(MaskSource::kOracle));
  streamDataset(dataset, slam, true);
  const dense::DenseMap map = slam.denseMap();
  EXPECT_GT(map.static_points.size(), 1000u);
  EXPECT_EQ(map.static_points.colours.size(), map.static_points.size());
}

// The map a stream saves starts a later stream and a later `segslam run` alike: both localise in
// it through the one pipeline and give the same trajectory, and localisation leaves it whole.
TEST(StreamingSlam, SavedMapStartsAStreamAndARunAlike) {
  const ScopedTempDir dir;
  const auto dataset = syntheticDataset();
  const auto map_file = dir.path() / "session.map";
  {
    auto options = deterministicOptions(MaskSource::kOracle);
    options.build_map = false;
    StreamingSlam first(dataset.camera(), options);
    streamDataset(dataset, first, true);
    EXPECT_GT(first.saveMap(map_file), 0u);
    EXPECT_TRUE(first.finished());
  }
  auto options = deterministicOptions(MaskSource::kOracle);
  options.build_map = false;
  options.map_file.load = map_file;
  options.map_file.localize_only = true;
  StreamingSlam second(dataset.camera(), options);
  ASSERT_TRUE(second.loadedMap().has_value());
  const std::size_t loaded_points = second.loadedMap()->contents.points.size();
  EXPECT_GT(loaded_points, 100u);
  const auto streamed = streamDataset(dataset, second, true);
  EXPECT_EQ(second.loadedPointsLeft(), loaded_points);
  EXPECT_GT(streamed.size(), dataset.size() * 9 / 10);

  SequenceRunOptions run_options;
  run_options.slam.deterministic = true;
  run_options.masks.source = MaskSource::kOracle;
  run_options.build_map = false;
  run_options.map_file = options.map_file;
  const auto run = runSequence(dataset, run_options, dir.path() / "run", {});
  ASSERT_TRUE(run.evaluation.has_value());
  const core::Trajectory& run_trajectory = run.evaluation->estimate;
  ASSERT_EQ(run_trajectory.size(), streamed.size());
  for (std::size_t i = 0; i < streamed.size(); ++i) {
    EXPECT_TRUE(streamed[i].T_wc.isApprox(run_trajectory[i].T_wc, 1e-12)) << "pose " << i;
  }
}

TEST(StreamingSlam, AMapThatIsNotThereIsAnErrorNamingIt) {
  const ScopedTempDir dir;
  const auto dataset = syntheticDataset();
  auto options = deterministicOptions(MaskSource::kNone);
  options.map_file.load = dir.path() / "absent.map";
  try {
    StreamingSlam slam(dataset.camera(), options);
    FAIL() << "an absent map was loaded";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("absent.map"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace segslam::system
