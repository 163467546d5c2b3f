#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "segslam/io/trajectory_io.h"
#include "segslam/testing/test_support.h"

namespace segslam::eval {
namespace {

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs `segslam <arguments>`, capturing stdout and stderr in files of `temp`.
CliRun runCli(const std::string& arguments, const std::filesystem::path& temp) {
  const auto out = temp / "stdout.txt";
  const auto err = temp / "stderr.txt";
  const std::string command =
      quoted(SEGSLAM_CLI_PATH) + " " + arguments + " > " + quoted(out) + " 2> " + quoted(err);
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, segslam::testing::fileContents(out),
          segslam::testing::fileContents(err)};
}

std::string referenceArguments(const std::filesystem::path& dir) {
  return "eval --gt " + quoted(dir / "walking_xyz_groundtruth.txt") + " --est " +
         quoted(dir / "walking_xyz_dynaslam_rgbd.txt");
}

TEST(EvalCli, WritesJsonAndPlotsForTheReferencePair) {
  SEGSLAM_REQUIRE_SHARED(dir, "reference_trajectories");
  const segslam::testing::ScopedTempDir temp;
  const auto json_file = temp.path() / "results.json";
  const auto plots = temp.path() / "plots";
  const auto aligned = temp.path() / "aligned.txt";
  const auto run = runCli(referenceArguments(dir) + " --json " + quoted(json_file) + " --plots " +
                              quoted(plots) + " --aligned-out " + quoted(aligned),
                          temp.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("ATE (SE3, 757 pairs)  "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("rmse 0.016314 m"), std::string::npos) << run.out;

  const auto json = nlohmann::json::parse(segslam::testing::fileContents(json_file));
  EXPECT_EQ(json["ate"]["pairs"], 757);
  EXPECT_NEAR(json["ate"]["translational"]["rmse"].get<double>(), 0.016314, 1e-4);
  EXPECT_NEAR(json["rpe"]["translational"]["rmse"].get<double>(), 0.021809, 1e-4);
  EXPECT_NEAR(json["rpe"]["rotational"]["rmse"].get<double>(), 0.618397, 1e-3);

  for (const auto* name :
       {"trajectory_top.svg", "trajectory_xyz.svg", "ate_error.svg", "rpe_error.svg"}) {
    const auto svg = segslam::testing::fileContents(plots / name);
    EXPECT_EQ(svg.rfind("<svg", 0), 0u) << name;
    EXPECT_NE(svg.find("<polyline"), std::string::npos) << name;
  }
  EXPECT_EQ(io::readTumTrajectory(aligned).size(), 757u);
}

TEST(EvalCli, JsonWithoutFileGoesToStdoutInsteadOfTheTable) {
  SEGSLAM_REQUIRE_SHARED(dir, "reference_trajectories");
  const segslam::testing::ScopedTempDir temp;
  const auto run = runCli(referenceArguments(dir) + " --rpe-unit f --json", temp.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["options"]["rpe"]["delta_unit"], "f");
  EXPECT_NEAR(json["rpe"]["translational"]["rmse"].get<double>(), 0.012535, 1e-4);
  EXPECT_NEAR(json["rpe"]["rotational"]["rmse"].get<double>(), 0.398473, 1e-3);
}

TEST(EvalCli, MissingFileFailsNamingIt) {
  const segslam::testing::ScopedTempDir temp;
  const auto gt = temp.path() / "gt.txt";
  std::ofstream(gt) << "1.0 0 0 0 0 0 0 1\n2.0 0 0 0 0 0 0 1\n";
  const auto missing = temp.path() / "no_such_estimate.txt";
  const auto run = runCli("eval --gt " + quoted(gt) + " --est " + quoted(missing), temp.path());
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(run.err.rfind("error: " + missing.string(), 0), 0u) << run.err;
}

TEST(EvalCli, MissingOptionIsAUsageError) {
  const segslam::testing::ScopedTempDir temp;
  const auto run = runCli("eval --est x.txt", temp.path());
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("--gt"), std::string::npos) << run.err;
}

TEST(EvalCli, HelpShowsDefaults) {
  const segslam::testing::ScopedTempDir temp;
  const auto run = runCli("eval --help", temp.path());
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("--max-diff"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("0.02"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("--rpe-unit"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace segslam::eval
