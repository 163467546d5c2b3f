#include "segslam/system/frame_player.h"

#include <gtest/gtest.h>

#include "segslam/io/io_test_support.h"
#include "segslam/synth/generator.h"
#include "segslam/testing/test_support.h"

namespace segslam::system {
namespace {

using testing::ScopedTempDir;

io::TumDataset smallSequence(const ScopedTempDir& dir) {
  synth::SynthOptions options;
  options.frames = 12;
  options.width = 160;
  options.height = 120;
  options.people = 1;
  synth::generateSequence(options, dir.path() / "sequence");
  return io::TumDataset::open(dir.path() / "sequence");
}

MaskSourceOptions geometricMasks() {
  MaskSourceOptions options;
  options.source = MaskSource::kGeometric;
  return options;
}

// The frames and masks one player gives, in order.
std::vector<PlayedFrame> playAll(const io::TumDataset& dataset, bool load_ahead) {
  FrameMaskSource masks(dataset, geometricMasks(), /*synchronous=*/true);
  FramePlayer player(dataset, masks, {io::FrameLayers{}, false, load_ahead});
  std::vector<PlayedFrame> played;
  for (std::size_t i = 0; i < dataset.size(); ++i)
    played.push_back(player.take(i, dataset.size() - 1));
  return played;
}

TEST(FramePlayer, LoadingAheadGivesTheSameFramesAndMasksInOrder) {
  const ScopedTempDir dir;
  const io::TumDataset dataset = smallSequence(dir);
  const auto ahead = playAll(dataset, true);
  const auto in_turn = playAll(dataset, false);
  ASSERT_EQ(ahead.size(), dataset.size());
  ASSERT_EQ(in_turn.size(), dataset.size());
  for (std::size_t i = 0; i < dataset.size(); ++i) {
    const io::RgbdFrame expected = dataset.loadFrame(i);
    EXPECT_EQ(ahead[i].frame.timestamp, expected.timestamp) << i;
    EXPECT_EQ(cv::norm(ahead[i].frame.rgb, expected.rgb, cv::NORM_INF), 0.0) << i;
    ASSERT_EQ(ahead[i].masks.dynamic.size(), expected.rgb.size()) << i;
    // Synchronous segmentation: the masks do not depend on the thread that made them.
    EXPECT_EQ(cv::norm(ahead[i].masks.dynamic, in_turn[i].masks.dynamic, cv::NORM_INF), 0.0) << i;
  }
}

// A damaged frame comes back flagged and never reaches the masks: the frames after it are numbered
// as SLAM numbers the frames it is handed.
TEST(FramePlayer, DamagedFramesAreFlaggedAndNotNumbered) {
  const ScopedTempDir dir;
  const io::TumDataset whole = smallSequence(dir);
  const auto jpeg =
      io::testing::replaceByTruncatedJpeg(dir.path() / "sequence", whole.frames()[3].rgb_path);
  const io::TumDataset dataset = io::TumDataset::open(dir.path() / "sequence");
  for (const bool load_ahead : {true, false}) {
    const auto played = playAll(dataset, load_ahead);
    ASSERT_EQ(played.size(), dataset.size());
    ASSERT_TRUE(played[3].damage) << load_ahead;
    EXPECT_EQ(*played[3].damage, jpeg.string() +
                                     ": damaged image: the JPEG data stops before its end marker "
                                     "(FF D9): the file is truncated");
    EXPECT_TRUE(played[3].frame.rgb.empty());
    EXPECT_TRUE(played[3].masks.dynamic.empty());
    for (std::size_t i = 0; i < played.size(); ++i) {
      if (i == 3) continue;
      EXPECT_FALSE(played[i].damage) << i;
      EXPECT_EQ(played[i].frame_id, i < 3 ? i : i - 1) << i;
      EXPECT_EQ(played[i].masks.dynamic.size(), whole.loadFrame(0).rgb.size()) << i;
    }
  }
}

TEST(FramePlayer, RealtimePlaybackWaitsForEachFramesArrival) {
  const ScopedTempDir dir;
  const io::TumDataset dataset = smallSequence(dir);
  FrameMaskSource masks(dataset, geometricMasks(), /*synchronous=*/true);
  FramePlayer player(dataset, masks, {io::FrameLayers{}, true, true});
  const auto start = std::chrono::steady_clock::now();
  const std::size_t last = 3;
  for (std::size_t i = 0; i <= last; ++i) static_cast<void>(player.take(i, last));
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(elapsed, dataset.loadFrame(last).timestamp - dataset.loadFrame(0).timestamp);
}

}  // namespace
}  // namespace segslam::system
