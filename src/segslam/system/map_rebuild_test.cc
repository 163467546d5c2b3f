#include "segslam/system/map_rebuild.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "segslam/io/trajectory_io.h"
#include "segslam/testing/test_support.h"

namespace segslam::system {
namespace {

TEST(MapRebuild, NetworkLabelsOfTheKeyFramesGiveObjects) {
  SEGSLAM_REQUIRE_SHARED(fr1, "tum_fr1_xyz_300");
  const auto dataset = io::TumDataset::open(fr1);
  const testing::ScopedTempDir run;
  // Three keyframes, as an object must be seen by three; the camera hardly moves meanwhile.
  core::Trajectory keyframes;
  for (std::size_t k = 0; k < 3; ++k) {
    keyframes.append(dataset.frames()[k].timestamp, geometry::Pose::Identity());
  }
  io::writeTumTrajectory(run.path() / "KeyFrameTrajectory.txt", keyframes, "three keyframes");

  MapRebuildOptions options;
  options.model_config =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";
  options.model_file = *testing::sharedDir() / "models" / "espnetv2_voc_384.onnx";
  const MapSummary summary = rebuildMap(dataset, run.path(), options);
  EXPECT_EQ(summary.keyframes, 3u);
  ASSERT_GT(summary.objects, 0u);

  std::ifstream index(run.path() / "map" / "objects.json");
  const auto objects = nlohmann::json::parse(index)["objects"];
  bool monitor = false;
  for (const auto& object : objects) {
    if (object["label"] == "monitor" && !object["dynamic"].get<bool>()) monitor = true;
  }
  EXPECT_TRUE(monitor) << objects.dump();
}

}  // namespace
}  // namespace segslam::system
