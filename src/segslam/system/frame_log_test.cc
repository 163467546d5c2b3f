#include "segslam/system/frame_log.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::system {
namespace {

using testing::ScopedTempDir;

FrameStats frame(std::uint64_t id, tracking::TrackingState state) {
  FrameStats stats;
  stats.frame_id = id;
  stats.timestamp = 1.5 + static_cast<double>(id) / 30.0;
  stats.tracking_ms = 10.0 + static_cast<double>(id);
  stats.extraction_ms = 4.0;
  stats.keypoints = 1000;
  stats.matches = 300;
  stats.state = state;
  stats.keyframe = id == 0;
  stats.live_keyframes = 1;
  stats.live_map_points = 500;
  return stats;
}

std::string lineOf(const std::filesystem::path& file, int number) {
  std::ifstream in(file);
  std::string line;
  for (int i = 0; i <= number; ++i) std::getline(in, line);
  return line;
}

TEST(FrameLog, WritesARowPerFrame) {
  const ScopedTempDir dir;
  const auto file = dir.path() / "frame_log.csv";
  FrameLog log(file);
  log.add(frame(0, tracking::TrackingState::kOk));
  log.close();
  EXPECT_EQ(lineOf(file, 0),
            "frame,timestamp,mask_ms,extraction_ms,tracking_ms,keypoints,matches,state,keyframe,"
            "live_keyframes,live_map_points");
  EXPECT_EQ(lineOf(file, 1), "0,1.500000,0.000,4.000,10.000,1000,300,ok,1,1,500");
}

TEST(FrameLog, KeepsWhatTheRunSummaryNeeds) {
  const ScopedTempDir dir;
  FrameLog log(dir.path() / "frame_log.csv");
  log.add(frame(0, tracking::TrackingState::kOk));
  log.add(frame(1, tracking::TrackingState::kLost));
  log.add(frame(2, tracking::TrackingState::kLost));
  log.close();
  EXPECT_EQ(log.trackingMs(), (std::vector<double>{10.0, 11.0, 12.0}));
  EXPECT_EQ(log.extractionMs(), (std::vector<double>{4.0, 4.0, 4.0}));
  EXPECT_EQ(log.lostFrames(), 2U);
  EXPECT_EQ(lineOf(dir.path() / "frame_log.csv", 3).find("2,"), 0U);
}

TEST(FrameLog, AnUnwritableFileIsNamed) {
  const ScopedTempDir dir;
  const auto file = dir.path() / "missing_folder" / "frame_log.csv";
  try {
    FrameLog log(file);
    FAIL() << "no error";
  } catch (const util::Error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace segslam::system
