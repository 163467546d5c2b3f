#include "segslam/viewer/run_contents.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"
#include "segslam/viewer/test_run_folder.h"

namespace segslam::viewer {
namespace {

using testing::ScopedTempDir;

TEST(ViewerRunContents, RunWithoutMapListsTrajectoriesOnly) {
  const ScopedTempDir dir;
  fixtures::writeRunFolder(dir.path(), /*with_map=*/false);
  const auto contents = describeRun(dir.path());
  EXPECT_EQ(contents.estimate, std::filesystem::path("CameraTrajectory.txt"));
  EXPECT_EQ(contents.keyframes, std::filesystem::path("KeyFrameTrajectory.txt"));
  EXPECT_FALSE(contents.ground_truth);
  EXPECT_FALSE(contents.map);
  const auto json = runContentsJson(contents, "/run/");
  EXPECT_EQ(json["trajectories"]["estimate"], "/run/CameraTrajectory.txt");
  EXPECT_TRUE(json["trajectories"]["ground_truth"].is_null());
  EXPECT_TRUE(json["map"].is_null());
}

TEST(ViewerRunContents, MapFilesAndObjectsBecomeUrls) {
  const ScopedTempDir dir;
  fixtures::writeRunFolder(dir.path(), /*with_map=*/true);
  const auto contents = describeRun(dir.path());
  ASSERT_TRUE(contents.map);
  ASSERT_EQ(contents.map->objects.size(), 3u);
  EXPECT_EQ(contents.map->objects[1].label, "chair");
  EXPECT_EQ(contents.map->objects[1].instance, 2);
  EXPECT_TRUE(contents.map->objects[2].dynamic);
  const auto json = runContentsJson(contents, "/run/");
  EXPECT_EQ(json["map"]["static"], "/run/map/static.ply");
  EXPECT_EQ(json["map"]["dynamic"], "/run/map/dynamic.ply");
  EXPECT_DOUBLE_EQ(json["map"]["voxel_size"].get<double>(), 0.05);
  EXPECT_EQ(json["map"]["objects"][0]["url"], "/run/map/objects/chair_1.ply");
  EXPECT_EQ(json["map"]["objects"][0]["points"], 16);
}

TEST(ViewerRunContents, TheOccupancyMapIsALayerWhenTheRunBuiltOne) {
  const ScopedTempDir dir;
  fixtures::writeRunFolder(dir.path(), /*with_map=*/true);
  EXPECT_TRUE(runContentsJson(describeRun(dir.path()), "/run/")["map"]["occupancy"].is_null());
  std::ofstream(dir.path() / "map" / "occupancy.json") << "{}";
  fixtures::writePly(dir.path() / "map" / "occupancy_occupied.ply",
                     fixtures::grid(0.0f, 1.0f, 2, 9));
  auto json = runContentsJson(describeRun(dir.path()), "/run/");
  EXPECT_EQ(json["map"]["occupancy"]["info"], "/run/map/occupancy.json");
  EXPECT_EQ(json["map"]["occupancy"]["voxels"], "/run/map/occupancy_occupied.ply");
  EXPECT_TRUE(json["map"]["occupancy"]["grid"].is_null());
  std::ofstream(dir.path() / "map" / "occupancy_2d.pgm") << "P5 1 1 255\n";
  json = runContentsJson(describeRun(dir.path()), "/run/");
  EXPECT_EQ(json["map"]["occupancy"]["grid"], "/run/map/occupancy_2d.pgm");
}

TEST(ViewerRunContents, EachSavedSessionIsALayer) {
  const ScopedTempDir dir;
  fixtures::writeRunFolder(dir.path(), /*with_map=*/false);
  EXPECT_TRUE(describeRun(dir.path()).sessions.empty());
  EXPECT_EQ(runContentsJson(describeRun(dir.path()), "/run/")["sessions"].size(), 0u);
  for (int session : {0, 1}) {
    for (const char* kind : {"points", "keyframes"}) {
      fixtures::writePly(dir.path() / "map_sessions" /
                             ("session_" + std::to_string(session) + "_" + kind + ".ply"),
                         fixtures::grid(0.0f, 1.0f, 2, 200));
    }
  }
  const auto contents = describeRun(dir.path());
  ASSERT_EQ(contents.sessions.size(), 2u);
  EXPECT_EQ(contents.sessions[1].session, 1);
  const auto json = runContentsJson(contents, "/run/");
  EXPECT_EQ(json["sessions"][1]["points"], "/run/map_sessions/session_1_points.ply");
  EXPECT_EQ(json["sessions"][0]["keyframes"], "/run/map_sessions/session_0_keyframes.ply");
}

TEST(ViewerRunContents, MissingRunFolderIsAnError) {
  const ScopedTempDir dir;
  EXPECT_THROW(describeRun(dir.path() / "absent"), util::Error);
}

void expectIndexRejected(const std::string& index_text, const std::string& message_part) {
  const ScopedTempDir dir;
  fixtures::writeRunFolder(dir.path(), /*with_map=*/true);
  std::ofstream(dir.path() / "map" / "objects.json") << index_text;
  try {
    describeRun(dir.path());
    ADD_FAILURE() << "accepted: " << index_text;
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("objects.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(message_part), std::string::npos) << e.what();
  }
}

TEST(ViewerRunContents, MalformedObjectsIndexNamesTheFile) {
  expectIndexRejected("{\"objects\": [", "not a JSON object");
  expectIndexRejected("{\"objects\": 3}", "\"objects\" must be an array");
  expectIndexRejected(R"({"objects": [{"id": "a", "file": "objects/chair_1.ply"}]})", "\"label\"");
  expectIndexRejected(R"({"objects": [{"id": "a", "label": "b", "file": "objects/none.ply"}]})",
                      "does not exist");
  expectIndexRejected(R"({"objects": [{"id": "a", "label": "b", "file": "../../etc/passwd"}]})",
                      "outside the map folder");
}

}  // namespace
}  // namespace segslam::viewer
