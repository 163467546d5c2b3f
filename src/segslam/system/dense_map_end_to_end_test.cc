#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "segslam/dense/ply_io.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/synth/generator.h"
#include "segslam/system/map_evaluation.h"
#include "segslam/system/map_rebuild.h"
#include "segslam/system/sequence_runner.h"
#include "segslam/testing/synth_sequences.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

// A short synthetic sequence with a walking person, run with oracle masks: the run writes the
// map files, the map keeps the person out and covers the scene, and `segslam map` rebuilds it.
namespace segslam::system {
namespace {

using testing::ScopedTempDir;

TEST(DenseMapEndToEnd, SyntheticRunWritesACleanMapThatRebuilds) {
  const ScopedTempDir dir;
  synth::SynthOptions synth_options;
  synth_options.frames = 45;
  synth_options.people = 1;
  synth_options.seed = 3;
  const auto dataset = io::TumDataset::open(testing::sharedSequence(synth_options));
  SequenceRunOptions options;
  options.slam.deterministic = true;
  options.masks.source = MaskSource::kOracle;
  const auto run_dir = dir.path() / "run";
  const auto summary = runSequence(dataset, options, run_dir, [](const FrameStats&) {});

  ASSERT_TRUE(summary.map);
  EXPECT_GE(summary.map->keyframes, summary.keyframes);  // culled ones included
  EXPECT_GT(summary.map->static_points, 10000u);
  EXPECT_GT(summary.map->objects, 0u);
  const auto static_map = dense::readPly(run_dir / "map" / "static.ply");
  EXPECT_EQ(static_map.size(), summary.map->static_points);
  EXPECT_EQ(dense::readPly(run_dir / "map" / "dynamic.ply").size(), summary.map->dynamic_points);
  std::ifstream index_file(run_dir / "map" / "objects.json");
  const auto index = nlohmann::json::parse(index_file);
  EXPECT_DOUBLE_EQ(index.at("voxel_size").get<double>(), 0.01);
  ASSERT_EQ(index.at("objects").size(), summary.map->objects);
  for (const auto& object : index.at("objects")) {
    const auto file = run_dir / "map" / object.at("file").get<std::string>();
    EXPECT_EQ(dense::readPly(file).size(), object.at("points").get<std::size_t>()) << file;
    EXPECT_EQ(object.at("id").get<std::string>(),
              object.at("label").get<std::string>() + "_" +
                  std::to_string(object.at("instance").get<int>()));
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_LE(object.at("bbox_min")[axis].get<double>(),
                object.at("centroid")[axis].get<double>());
      EXPECT_GE(object.at("bbox_max")[axis].get<double>(),
                object.at("centroid")[axis].get<double>());
    }
  }

  const auto evaluation = evaluateMap(dataset, run_dir, {});
  ASSERT_TRUE(evaluation.on_dynamic_share);
  EXPECT_LT(*evaluation.on_dynamic_share, 0.01);
  EXPECT_GT(*evaluation.completeness, 0.5);
  EXPECT_GT(*evaluation.accuracy, 0.8);
  EXPECT_FALSE(evaluation.near_person_path_share);  // no persons_gt.txt

  MapRebuildOptions coarse;
  coarse.oracle_masks = true;
  coarse.map.keyframe.voxel_size = 0.03;
  const auto rebuilt = rebuildMap(dataset, run_dir, coarse);
  EXPECT_EQ(rebuilt.keyframes, summary.keyframes);
  EXPECT_LT(rebuilt.static_points, summary.map->static_points / 4);
  EXPECT_EQ(dense::readPly(run_dir / "map" / "static.ply").size(), rebuilt.static_points);
}

TEST(DenseMapEndToEnd, RebuildNamesAMissingTrajectory) {
  const ScopedTempDir dir;
  synth::SynthOptions synth_options;
  synth_options.frames = 3;
  synth_options.people = 0;
  synth::generateSequence(synth_options, dir.path() / "sequence");
  const auto dataset = io::TumDataset::open(dir.path() / "sequence");
  try {
    (void)rebuildMap(dataset, dir.path() / "no_run", {});
    FAIL() << "expected an error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("KeyFrameTrajectory.txt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace segslam::system
