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
  core::Trajectory keyframes;
  keyframes.append(dataset.frames()[0].timestamp, geometry::Pose::Identity());
  io::writeTumTrajectory(run.path() / "KeyFrameTrajectory.txt", keyframes, "one keyframe");

  MapRebuildOptions options;
  options.model_config =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";
  options.model_file = *testing::sharedDir() / "models" / "espnetv2_voc_384.onnx";
  const MapSummary summary = rebuildMap(dataset, run.path(), options);
  EXPECT_EQ(summary.keyframes, 1u);
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
