#include "segslam/system/map_persistence.h"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <sstream>

#include "segslam/io/trajectory_io.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/occupancy/map_files.h"
#include "segslam/occupancy/occupancy_map.h"
#include "segslam/place/vocabulary.h"
#include "segslam/synth/generator.h"
#include "segslam/synth/room_layout.h"
#include "segslam/system/sequence_runner.h"
#include "segslam/testing/synth_sequences.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

// Sessions on a synthetic lap around the room (320x240, Kinect-like depth noise): the first
// builds a map on frames 0-149 and saves it, the next ones load it.
namespace segslam::system {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMapFrames = 150;

fs::path vocabularyFile() {
  return fs::path(SEGSLAM_SOURCE_DIR) / "config" / place::kDefaultVocabularyFile;
}

SequenceRunOptions sessionOptions() {
  SequenceRunOptions options;
  options.slam.deterministic = true;
  options.slam.loop_closing = false;
  options.build_map = false;
  options.masks.source = MaskSource::kNone;
  options.slam.relocalisation_vocabulary =
      std::make_shared<const place::Vocabulary>(place::Vocabulary::load(vocabularyFile()));
  options.map_file.vocabulary_file = vocabularyFile();
  options.map_file.frames_to_localise = 10;
  return options;
}

// The frames of `source` from frame `first` on, as a dataset of its own (images linked).
fs::path framesFrom(const fs::path& source, std::size_t first, const fs::path& out) {
  const auto dataset = io::TumDataset::open(source);
  const double first_timestamp = dataset.frames()[first].timestamp - 1e-4;
  fs::create_directories(out);
  for (const auto& entry : fs::directory_iterator(source)) {
    const auto target = out / entry.path().filename();
    if (entry.is_directory()) {
      fs::create_directory_symlink(fs::absolute(entry.path()), target);
      continue;
    }
    std::ifstream in(entry.path());
    std::ofstream copy(target);
    const bool list =
        entry.path().extension() == ".txt" && entry.path().filename() != "groundtruth.txt";
    for (std::string line; std::getline(in, line);) {
      if (list && !line.empty() && line[0] != '#' && std::stod(line) < first_timestamp) continue;
      copy << line << "\n";
    }
  }
  return out;
}

class MapSessions : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::ScopedTempDir;
    auto options = sessionOptions();
    options.max_frames = kMapFrames;
    options.map_file.save = mapFile();
    first_session_ = new SequenceRunSummary(
        runSequence(io::TumDataset::open(lap()), options, dir_->path() / "session1", {}));
  }
  static void TearDownTestSuite() {
    delete first_session_;
    delete dir_;
  }
  static fs::path lap() { return testing::sharedSequence(testing::noisyRoomLap(240)); }
  static fs::path mapFile() { return dir_->path() / "session1.map"; }

  static SequenceRunSummary runSession(const fs::path& dataset, SequenceRunOptions options,
                                       const std::string& name) {
    options.map_file.load = mapFile();
    return runSequence(io::TumDataset::open(dataset), options, dir_->path() / name, {});
  }

  static testing::ScopedTempDir* dir_;
  static SequenceRunSummary* first_session_;
};

testing::ScopedTempDir* MapSessions::dir_ = nullptr;
SequenceRunSummary* MapSessions::first_session_ = nullptr;

// Largest distance between the positions two trajectories give the same timestamps.
double largestDifference(const core::Trajectory& a, const core::Trajectory& b) {
  double largest = 0.0;
  for (const auto& pose : a.poses()) {
    const auto other = b.poseAt(pose.timestamp, 1e-3);
    if (!other) return 1e9;
    largest = std::max(largest, (pose.T_wc.translation() - other->translation()).norm());
  }
  return largest;
}

TEST_F(MapSessions, SavingALoadedMapAfterLocalisationOnlyGivesTheSameBytes) {
  ASSERT_EQ(first_session_->tracked_frames, kMapFrames);
  const std::string saved = testing::fileContents(mapFile());
  EXPECT_EQ(map::encodeMapFile(map::readMapFile(mapFile())), saved);

  auto options = sessionOptions();
  options.map_file.localize_only = true;
  options.map_file.save = dir_->path() / "localised.map";
  options.max_frames = 40;
  const auto summary =
      runSession(framesFrom(lap(), 100, dir_->path() / "from100"), options, "localise_only");
  ASSERT_TRUE(summary.map_file);
  EXPECT_EQ(summary.map_file->first_tracked_frame, 0U);
  EXPECT_EQ(summary.lost_frames, 0U);
  EXPECT_EQ(summary.map_file->loaded_points_culled, 0U);
  EXPECT_EQ(testing::fileContents(dir_->path() / "localised.map"), saved);
}

// Frames [first, first + count) of `dataset` as a system restored from `contents` tracks them,
// localisation only.
core::Trajectory trackInRestoredMap(const io::TumDataset& dataset,
                                    const map::MapFileContents& contents, std::size_t first,
                                    std::size_t count) {
  auto options = sessionOptions().slam;
  options.tracker.localize_only = true;
  SlamSystem slam(dataset.camera(), options);
  slam.restoreMap(contents);
  for (std::size_t i = first; i < first + count; ++i) {
    const auto frame = dataset.loadFrame(i, {.mask = false, .labels = false, .instances = false});
    slam.processFrame(frame.timestamp, frame.rgb, frame.depth, {});
  }
  slam.finish();
  return slam.cameraTrajectory();
}

TEST_F(MapSessions, ALoadedMapTracksFramesToThePosesTheMapInMemoryGaveThem) {
  const auto dataset = io::TumDataset::open(lap());
  auto options = sessionOptions().slam;
  SlamSystem built(dataset.camera(), options);
  for (std::size_t i = 0; i < kMapFrames; ++i) {
    const auto frame = dataset.loadFrame(i, {.mask = false, .labels = false, .instances = false});
    built.processFrame(frame.timestamp, frame.rgb, frame.depth, {});
  }
  built.finish();
  auto in_memory = built.captureMap();
  in_memory.sensor = built.mapSensor();
  const auto file = dir_->path() / "in_memory.map";
  map::writeMapFile(file, in_memory);

  const auto from_memory = trackInRestoredMap(dataset, in_memory, 100, 40);
  const auto from_file = trackInRestoredMap(dataset, map::readMapFile(file), 100, 40);
  ASSERT_EQ(from_file.size(), 40U);
  EXPECT_EQ(largestDifference(from_file, from_memory), 0.0);
  // The building run placed these frames while the map around them was still being refined:
  // the frames between keyframes differ by about a centimetre (those of keyframes agree to 2 mm),
  // and the loaded map's poses are the nearer to the ground truth.
  EXPECT_LT(largestDifference(from_file, built.cameraTrajectory()), 0.025);
}

TEST_F(MapSessions, RelocalisesFromAnotherStartingPointAndExtendsTheMap) {
  auto options = sessionOptions();
  options.max_frames = 120;  // frames 60-179: the last 30 beyond the loaded map
  options.map_file.save = dir_->path() / "extended.map";
  const auto summary =
      runSession(framesFrom(lap(), 60, dir_->path() / "from60"), options, "extend");
  ASSERT_TRUE(summary.map_file);
  ASSERT_TRUE(summary.map_file->first_tracked_frame);
  EXPECT_LE(*summary.map_file->first_tracked_frame, 5U);
  EXPECT_EQ(summary.lost_frames, *summary.map_file->first_tracked_frame);
  // In the loaded map's frame: session 1 started at the lap's first frame.
  const auto dataset = io::TumDataset::open(lap());
  const auto& truth = *dataset.groundTruth();
  const auto estimate = io::readTumTrajectory(dir_->path() / "extend" / "CameraTrajectory.txt");
  const geometry::Pose origin = truth.poses().front().T_wc;
  double largest = 0.0;
  for (const auto& pose : estimate.poses()) {
    const auto true_pose = truth.poseAt(pose.timestamp, 1e-3);
    ASSERT_TRUE(true_pose) << pose.timestamp;
    const geometry::Pose expected = origin.inverse() * *true_pose;
    largest = std::max(largest, (expected.translation() - pose.T_wc.translation()).norm());
  }
  EXPECT_LT(largest, 0.05);

  const auto extended = map::readMapFile(dir_->path() / "extended.map");
  const auto loaded = map::readMapFile(mapFile());
  EXPECT_GT(extended.keyframes.size(), loaded.keyframes.size());
  EXPECT_EQ(extended.keyframes.back().session, 1U);
  EXPECT_GT(extended.keyframes.back().id, loaded.keyframes.back().id);
  EXPECT_EQ(extended.keyframes.front().session, 0U);
}

TEST_F(MapSessions, AMapOfAnotherCameraOrVocabularyIsRefusedNamingTheFile) {
  const auto dataset = io::TumDataset::open(lap());
  const auto identity = runIdentity(sessionOptions().map_file, {});
  core::Camera other = dataset.camera();
  other.fx *= 1.01;
  SlamSystem slam(other, sessionOptions().slam);
  try {
    loadMapInto(slam, mapFile(), identity);
    FAIL() << "no error";
  } catch (const util::Error& e) {
    EXPECT_TRUE(
        std::string(e.what()).starts_with(mapFile().string() + ": map made with another camera ("))
        << e.what();
  }
  auto other_vocabulary = identity;
  other_vocabulary.vocabulary_hash ^= 1;
  SlamSystem same_camera(dataset.camera(), sessionOptions().slam);
  try {
    loadMapInto(same_camera, mapFile(), other_vocabulary);
    FAIL() << "no error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find(": map made with another vocabulary ("), std::string::npos)
        << e.what();
  }
}

TEST_F(MapSessions, ACameraThatNeverSeesTheLoadedMapStopsTheRunNamingTheFile) {
  const auto blank = framesFrom(lap(), 0, dir_->path() / "blank");
  fs::remove(blank / "rgb");
  fs::create_directory(blank / "rgb");
  const auto dataset = io::TumDataset::open(lap());
  for (const auto& frame : dataset.frames()) {
    cv::imwrite((blank / "rgb" / frame.rgb_path.filename()).string(),
                cv::Mat(240, 320, CV_8UC3, cv::Scalar(128, 128, 128)));
  }
  // Twenty frames stop at the tenth (--localise-within); five, shorter than that, at their last.
  for (const auto& [frames, deadline] : {std::pair{20, 10}, std::pair{5, 5}}) {
    auto options = sessionOptions();
    options.max_frames = frames;
    try {
      runSession(blank, options, "blank_run");
      ADD_FAILURE() << "no error for " << frames << " frames";
    } catch (const util::Error& e) {
      EXPECT_EQ(std::string(e.what()),
                mapFile().string() +
                    ": the camera was not localised in this map within its first " +
                    std::to_string(deadline) + " frames (another place, or another map?)");
    }
  }
}

// Session 2 plays again the frames session 1 mapped, now with two people walking through the
// room (oracle masks). People hide loaded points and new keyframes see them from elsewhere: that
// is no evidence that a point is gone, so the loaded map stays (only points seen through or on a
// person go), and no frame is lost. Measured: 25 of 2950 loaded points culled (0.8 %); 419
// (14.2 %) when a loaded point went with its second-last keyframe or in a merge.
TEST_F(MapSessions, PeopleWalkingThroughARevisitLeaveTheLoadedMap) {
  auto crowded = testing::noisyRoomLap(240);
  crowded.people = 2;
  const auto generated = synth::generateSequence(crowded, dir_->path() / "crowded_lap");
  ASSERT_GT(generated.frames_with_person, 50);
  auto options = sessionOptions();
  options.masks.source = MaskSource::kOracle;
  options.max_frames = kMapFrames;
  const auto summary = runSession(dir_->path() / "crowded_lap", options, "crowded");
  ASSERT_TRUE(summary.map_file);
  EXPECT_EQ(summary.map_file->first_tracked_frame, 0U);
  EXPECT_EQ(summary.lost_frames, 0U);
  const auto& loaded = *summary.map_file;
  EXPECT_LE(loaded.loaded_points_culled, loaded.loaded_points / 20)
      << "of " << loaded.loaded_points << " loaded points";
}

// Loaded points of `map_file` near where chair_1 stood (within 0.4 m across the floor, below
// 1.2 m) and those of them left in `after`: the map frame is the lap's first camera.
std::pair<int, int> chairPointsLeft(const fs::path& map_file, const fs::path& after,
                                    const geometry::Pose& T_world_map) {
  const Eigen::Vector3d chair = synth::chairPush(1.0).start.translation();
  std::set<std::uint64_t> left;
  for (const auto& point : map::readMapFile(after).points) left.insert(point.id);
  std::pair<int, int> counts{0, 0};
  for (const auto& point : map::readMapFile(map_file).points) {
    const Eigen::Vector3d world = T_world_map * point.position;
    if ((world - chair).head<2>().norm() > 0.4 || world.z() > 1.2) continue;
    ++counts.first;
    counts.second += static_cast<int>(left.count(point.id));
  }
  return counts;
}

// Occupied voxels of a session's occupancy map (map frame) whose centre lies within 0.15 m of
// `place` across the floor (world z up) and between 0.1 and 0.6 m high: a chair's seat and legs.
int occupiedVoxelsAt(const fs::path& occupancy_file, const geometry::Pose& T_world_map,
                     const Eigen::Vector2d& place) {
  int count = 0;
  for (const auto& voxel : occupancy::voxelCentres(*occupancy::readOctree(occupancy_file), true)) {
    const Eigen::Vector3d world = T_world_map * voxel;
    if ((world.head<2>() - place).norm() <= 0.15 && world.z() >= 0.1 && world.z() <= 0.6) ++count;
  }
  return count;
}

// Session 1 maps the whole lap with chair_1 in place (the camera sees it in frames 155-235).
// Session 2 plays frames 150-239 of the lap where the chair was pushed 0.55 m away during frames
// 72-132, and, as the control, of the unchanged lap: the depth sees through where the chair was,
// in the SLAM map and in the dense map that session 1 left.
TEST_F(MapSessions, PointsOfAChairMovedSinceTheMapWasMadeAreCulled) {
  auto options = sessionOptions();
  options.build_map = true;
  options.map_file.save = dir_->path() / "whole_lap.map";
  runSequence(io::TumDataset::open(lap()), options, dir_->path() / "whole_lap", {});
  auto moved_lap = testing::noisyRoomLap(240);
  moved_lap.moved_furniture = true;

  const auto dataset = io::TumDataset::open(lap());
  const geometry::Pose T_world_map = dataset.groundTruth()->poses().front().T_wc;
  std::map<std::string, std::pair<int, int>> chair_points;
  std::map<std::string, std::size_t> dense_points_removed;
  const Eigen::Vector2d old_place = synth::chairPush(1.0).start.translation().head<2>();
  std::map<std::string, int> occupied_at_old_place;
  for (const auto& [name, sequence] :
       {std::pair{"moved", testing::sharedSequence(moved_lap)}, std::pair{"unchanged", lap()}}) {
    auto session = sessionOptions();
    session.build_map = true;
    session.map_file.load = dir_->path() / "whole_lap.map";
    session.map_file.save = dir_->path() / (std::string(name) + ".map");
    const auto summary =
        runSequence(io::TumDataset::open(
                        framesFrom(sequence, 150, dir_->path() / (std::string(name) + "_150"))),
                    session, dir_->path() / name, {});
    EXPECT_EQ(summary.lost_frames, 0U) << name;
    ASSERT_TRUE(summary.map) << name;
    dense_points_removed[name] = summary.map->earlier_points_removed;
    ASSERT_TRUE(summary.map->occupancy && summary.map->occupancy->continued_earlier) << name;
    const auto occupancy = dir_->path() / name / "map" / occupancy::kOccupancyFile;
    occupied_at_old_place[name] = occupiedVoxelsAt(occupancy, T_world_map, old_place);
    chair_points[name] =
        chairPointsLeft(dir_->path() / "whole_lap.map", *session.map_file.save, T_world_map);
  }
  const auto [mapped, left_unchanged] = chair_points["unchanged"];
  const int left_moved = chair_points["moved"].second;
  // Measured: 44 points on the chair, 42 left in the unchanged room, 16 after the chair moved.
  EXPECT_GE(mapped, 20);
  EXPECT_GE(left_unchanged, mapped * 8 / 10);
  EXPECT_LE(left_moved, mapped / 2) << "of " << mapped << " chair points";
  EXPECT_GT(dense_points_removed["moved"], 3 * dense_points_removed["unchanged"] + 100)
      << dense_points_removed["unchanged"] << " removed in the unchanged room";
  // The occupancy map carried on from session 1: the chair's old place is free once the camera
  // has seen through it; in the unchanged room the chair stays. (Its new place, under the table,
  // is out of these frames' view: OccupancyMap's own test has a moved box show up.) Measured:
  // 38 voxels in the unchanged room, 12 after the chair moved (19 when an earlier occupied voxel
  // was believed at 0.7, so that one view through it did not clear it).
  const int old_unchanged = occupied_at_old_place["unchanged"];
  EXPECT_GE(old_unchanged, 10);
  EXPECT_LE(occupied_at_old_place["moved"], old_unchanged / 2) << "of " << old_unchanged;
}

}  // namespace
}  // namespace segslam::system
