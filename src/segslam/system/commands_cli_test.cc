// The `segslam` commands that write output folders or read sequences, run as a user runs them:
// every error is one line naming what is wrong, and what can be computed is.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "segslam/io/io_test_support.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/testing/test_support.h"

namespace segslam::system {
namespace {

namespace fs = std::filesystem;

std::string inQuotes(const fs::path& path) { return "'" + path.string() + "'"; }

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs `segslam <arguments>`, capturing stdout and stderr in files of `temp`.
CommandResult runSegslam(const std::string& arguments, const fs::path& temp) {
  const auto out = temp / "stdout.txt";
  const auto err = temp / "stderr.txt";
  const std::string command =
      inQuotes(SEGSLAM_CLI_PATH) + " " + arguments + " > " + inQuotes(out) + " 2> " + inQuotes(err);
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, segslam::testing::fileContents(out),
          segslam::testing::fileContents(err)};
}

class CommandsCli : public ::testing::Test {
 protected:
  CommandsCli() {
    io::testing::writeTinyDataset(dataset_);
    std::ofstream(file_) << "a file, not a folder";
  }

  // Expects `arguments` to fail with exactly one error line, `error`, as its last output.
  void expectError(const std::string& arguments, const std::string& error) {
    const auto result = runSegslam(arguments, temp_.path());
    EXPECT_EQ(result.exit_code, 1) << arguments;
    const std::string line = "error: " + error + "\n";
    EXPECT_TRUE(result.err.ends_with(line)) << arguments << "\n" << result.err;
    EXPECT_EQ(result.err.find("error:"), result.err.size() - line.size()) << result.err;
  }

  segslam::testing::ScopedTempDir temp_;
  fs::path dataset_ = temp_.path() / "tiny";
  fs::path file_ = temp_.path() / "file.txt";
};

TEST_F(CommandsCli, AnOutputFolderThatCannotBeCreatedIsNamedByEveryCommand) {
  const fs::path out = file_ / "out";
  const std::string not_created =
      "cannot create output folder " + out.string() + ": Not a directory";
  const std::string data = " --dataset " + inQuotes(dataset_) + " --out " + inQuotes(out);
  expectError("run" + data + " --seg none", not_created);
  expectError("check" + data, not_created);
  expectError("eval masks" + data + " --seg oracle", not_created);
  expectError("eval loops" + data, not_created);
  expectError("synth --out " + inQuotes(out), not_created);
  expectError(
      "vocab train --images " + inQuotes(dataset_ / "rgb") + " --out " + inQuotes(out / "v.voc"),
      not_created);
  const std::string trajectories = "eval --gt " + inQuotes(dataset_ / "groundtruth.txt") +
                                   " --est " + inQuotes(dataset_ / "groundtruth.txt");
  expectError(trajectories + " --plots " + inQuotes(out), not_created);
  expectError(trajectories + " --json " + inQuotes(out / "e.json"), not_created);
  expectError(trajectories + " --aligned-out " + inQuotes(out / "a.txt"), not_created);

  const fs::path run = temp_.path() / "run";
  fs::create_directories(run);
  std::ofstream(run / "map") << "in the way";
  expectError("map --run " + inQuotes(run) + " --dataset " + inQuotes(dataset_),
              "cannot create output folder " + (run / "map").string() +
                  ": a file of that name is in the way");
}

TEST_F(CommandsCli, CheckCountsAFrameWithADamagedImage) {
  const auto frames = io::TumDataset::open(dataset_).frames();
  const auto jpeg = io::testing::replaceByTruncatedJpeg(dataset_, frames[2].rgb_path);
  const fs::path out = temp_.path() / "check";
  const auto result =
      runSegslam("check --dataset " + inQuotes(dataset_) + " --out " + inQuotes(out), temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("  damaged       1 frames skipped for damaged images"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.err.find("skipped: " + jpeg.string() + ": damaged image: the JPEG data stops"),
            std::string::npos)
      << result.err;
  const auto json =
      nlohmann::json::parse(segslam::testing::fileContents(out / "dataset_check.json"));
  EXPECT_EQ(json["frames"], 4);
  EXPECT_EQ(json["skipped_frames"], 1);

  const auto first = io::testing::replaceByTruncatedJpeg(dataset_, frames[0].rgb_path);
  io::testing::replaceByTruncatedJpeg(dataset_, frames[1].rgb_path);
  expectError("check --dataset " + inQuotes(dataset_) + " --out " + inQuotes(out),
              dataset_.string() +
                  ": more than half of the 4 frames have damaged images (3 so far; the first: " +
                  first.string() +
                  ": damaged image: the JPEG data stops before its end marker (FF D9): the file "
                  "is truncated)");
}

TEST_F(CommandsCli, EvalReportsTheAteWhenOnlyTheRpeIsImpossible) {
  const fs::path est = temp_.path() / "est.txt";
  io::writeTumTrajectory(est, io::readTumTrajectory(dataset_ / "groundtruth.txt"));
  const auto result =
      runSegslam("eval --gt " + inQuotes(dataset_ / "groundtruth.txt") + " --est " + inQuotes(est),
                 temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("ATE (SE3, 4 pairs)"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("not computed: the estimate spans 0.100 s (4 poses) and has 0 pose "
                            "pair(s) 1 s apart"),
            std::string::npos)
      << result.out;
}

// The run: `segslam run --dataset tum_fr1_xyz_300 --max-frames 20` tracked every frame,
// then failed on the RPE and wrote no summary.json.
TEST_F(CommandsCli, TwentyRealFramesRunAndReportTheRpeAsNotComputed) {
  SEGSLAM_REQUIRE_SHARED(sequence, "tum_fr1_xyz_300");
  const fs::path out = temp_.path() / "run";
  const auto result = runSegslam("run --dataset " + inQuotes(sequence) +
                                     " --max-frames 20 --seg none --no-map --out " + inQuotes(out),
                                 temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("  ATE        rmse "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("  RPE (1 s)  not computed: the estimate spans "), std::string::npos)
      << result.out;
  const auto summary = nlohmann::json::parse(segslam::testing::fileContents(out / "summary.json"));
  EXPECT_EQ(summary["frames"], 20);
  EXPECT_EQ(summary["skipped_frames"], 0);
  EXPECT_TRUE(summary["ate_rmse_m"].is_number());
  EXPECT_TRUE(summary["rpe_translational_rmse_m"].is_null());
  EXPECT_TRUE(summary["rpe_not_computed"].is_string());
}

// The report: `segslam run --dataset rgbd_bonn_crowd_300` stopped at a depth image that
// depth.txt lists and the sequence lacks, found no camera, and would have scored the markers'
// poses. As published, with no options, it runs; the ATE is against the camera's poses.
TEST_F(CommandsCli, ABonnSequenceRunsAsPublishedAgainstTheCamerasGroundTruth) {
  SEGSLAM_REQUIRE_SHARED(sequence, "rgbd_bonn_crowd_300");
  const fs::path out = temp_.path() / "run";
  auto result =
      runSegslam("run --dataset " + inQuotes(sequence) +
                     " --max-frames 40 --seg none --no-map --deterministic --out " + inQuotes(out),
                 temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("depth.txt:4: listed image " +
                            (sequence / "depth/1548339819.85514.png").string() +
                            " does not exist: left out"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.out.find("  absent     2 listed images not in the dataset"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("ground truth: Bonn motion-capture markers, converted to the camera"),
            std::string::npos)
      << result.out;
  const auto summary = nlohmann::json::parse(segslam::testing::fileContents(out / "summary.json"));
  EXPECT_EQ(summary["absent_images"], 2);
  EXPECT_EQ(summary["ground_truth"]["frame"], "bonn-markers");
  const auto evaluation =
      nlohmann::json::parse(segslam::testing::fileContents(out / "evaluation.json"));
  EXPECT_EQ(evaluation["ground_truth"]["frame"], "bonn-markers");

  // The ATE is the one against the dataset's documented camera poses (the shared folder's
  // groundtruth_camera.txt holds them); `eval` reads a Bonn groundtruth.txt the same way.
  const auto ateAgainst = [&](const std::string& ground_truth, const std::string& options) {
    const auto evaluated =
        runSegslam("eval --json --gt " + inQuotes(sequence / ground_truth) + " --est " +
                       inQuotes(out / "CameraTrajectory.txt") + options,
                   temp_.path());
    EXPECT_EQ(evaluated.exit_code, 0) << evaluated.err;
    return nlohmann::json::parse(evaluated.out)["ate"]["translational"]["rmse"].get<double>();
  };
  const double camera = ateAgainst("groundtruth_camera.txt", "");
  EXPECT_NEAR(summary["ate_rmse_m"].get<double>(), camera, 1e-6);
  EXPECT_NEAR(ateAgainst("groundtruth.txt", ""), camera, 1e-6);
  EXPECT_GT(std::abs(ateAgainst("groundtruth.txt", " --gt-frame camera") - camera), 1e-5);

  result = runSegslam("check --dataset " + inQuotes(sequence) + " --max-frames 5 --out " +
                          inQuotes(temp_.path() / "check"),
                      temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("  camera        preset bonn (from folder name)"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("depth.txt:211: " + (sequence / "depth/1548339826.76234.png").string() +
                            " is not in the dataset"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("(Bonn motion-capture markers, converted to the camera"),
            std::string::npos)
      << result.out;
}

// A build or checkout that cannot see its networks still runs, but says so even at
// `--log-level warn`: a build that quietly fell back to geometric masks and bag of words was
// measured as if it were the default (real crowd: 0.016 against 0.012 m).
TEST_F(CommandsCli, RunWarnsWhenItsNetworksAreMissing) {
  SEGSLAM_REQUIRE_SHARED(sequence, "tum_fr1_xyz_300");
  const fs::path config_dir = fs::path(SEGSLAM_SOURCE_DIR) / "config" / "models";
  const fs::path segmentation = temp_.path() / "segmentation.yaml";
  const fs::path backbone = temp_.path() / "backbone.yaml";
  segslam::testing::writeConfigNamingModel(config_dir / "espnetv2_voc_384.yaml", segmentation,
                                           temp_.path() / "absent_segmentation.onnx");
  segslam::testing::writeConfigNamingModel(config_dir / "tiny_darknet_imagenet.yaml", backbone,
                                           temp_.path() / "absent_backbone.onnx");
  const auto result = runSegslam(
      "--log-level warn run --dataset " + inQuotes(sequence) +
          " --max-frames 3 --no-map --deterministic --model-config " + inQuotes(segmentation) +
          " --backbone-config " + inQuotes(backbone) + " --out " + inQuotes(temp_.path() / "run"),
      temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("[warning] masks: geometric only, the segmentation network is missing"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("absent_segmentation.onnx"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("[warning] loop candidates: bag of words, the CNN backbone is missing"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("absent_backbone.onnx"), std::string::npos) << result.err;
}

// Masks carried by optical flow need a few dozen pixels; OpenCV's flow failed deep inside.
TEST_F(CommandsCli, MasksOnImagesTooSmallForOpticalFlowAreRefused) {
  const std::string run = "run --dataset " + inQuotes(dataset_) + " --no-map --out " +
                          inQuotes(temp_.path() / "run") + " --seg ";
  const std::string size =
      " x 32 pixels (they are carried between frames by optical flow); "
      "the camera's are 16 x 12 (--seg none or oracle work on any size)";
  expectError(run + "geometric", "geometric masks need images of at least 32" + size);
  expectError(run + "auto --model-config " +
                  inQuotes(fs::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml"),
              "fused masks need images of at least 32" + size);
}

TEST_F(CommandsCli, RunNamesAMapFileThatIsNotOne) {
  expectError("run --dataset " + inQuotes(dataset_) + " --seg none --no-map --load-map " +
                  inQuotes(file_) + " --out " + inQuotes(temp_.path() / "run"),
              file_.string() + ": not a segslam map file (no SEGSLMAP magic)");
}

// Save, then load and localise only: the map file is written again byte for byte.
TEST_F(CommandsCli, RunSavesAMapAndLocalisesInItWithoutChangingIt) {
  SEGSLAM_REQUIRE_SHARED(sequence, "tum_fr1_xyz_300");
  const fs::path first = temp_.path() / "first.map";
  const fs::path again = temp_.path() / "again.map";
  const std::string common = "run --dataset " + inQuotes(sequence) +
                             " --max-frames 30 --seg none --no-map --deterministic ";
  auto result = runSegslam(
      common + "--save-map " + inQuotes(first) + " --out " + inQuotes(temp_.path() / "run1"),
      temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("  map file   saved "), std::string::npos) << result.out;
  result = runSegslam(common + "--load-map " + inQuotes(first) + " --localize-only --save-map " +
                          inQuotes(again) + " --out " + inQuotes(temp_.path() / "run2"),
                      temp_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("first tracked frame 0"), std::string::npos) << result.out;
  EXPECT_EQ(segslam::testing::fileContents(again), segslam::testing::fileContents(first));
}

}  // namespace
}  // namespace segslam::system
