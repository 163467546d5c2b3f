#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "segslam/testing/test_support.h"
#include "segslam/util/text_file.h"

namespace segslam::synth {
namespace {

using segslam::testing::ScopedTempDir;

// Runs `segslam <arguments>` quietly; returns its exit status.
int runCli(const std::string& arguments, const std::filesystem::path& log) {
  const std::string command =
      std::string(SEGSLAM_CLI_PATH) + " " + arguments + " > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

TEST(SynthCli, WritesASequence) {
  const ScopedTempDir dir;
  const auto out = dir.path() / "sequence";
  ASSERT_EQ(runCli("synth --out '" + out.string() +
                       "' --frames 3 --width 64 --height 48 --people 1 --seed 5 "
                       "--depth-noise kinect --moved-furniture",
                   dir.path() / "log.txt"),
            0)
      << readAll(dir.path() / "log.txt");
  EXPECT_EQ(util::readTextRows(out / "rgb.txt").size(), 3u);
  EXPECT_EQ(util::readTextRows(out / "groundtruth.txt").size(), 3u);
  const auto meta = nlohmann::json::parse(readAll(out / "meta.json"));
  EXPECT_EQ(meta["options"]["seed"], 5);
  EXPECT_EQ(meta["options"]["people"], 1);
  EXPECT_EQ(meta["options"]["depth_noise"], "kinect");
  EXPECT_EQ(meta["options"]["moved_furniture"], true);
  const std::string log = readAll(dir.path() / "log.txt");
  EXPECT_NE(log.find("frames/s"), std::string::npos) << log;
}

TEST(SynthCli, RejectsInvalidOptions) {
  const ScopedTempDir dir;
  const std::string out = " --out '" + (dir.path() / "sequence").string() + "'";
  for (const std::string bad :
       {"--frames 0", "--width 10", "--path spiral", "--people 9", "--person-speed -1",
        "--depth-noise loud", "--path loop --frames 20", "--frames many"}) {
    EXPECT_NE(runCli("synth" + out + " " + bad, dir.path() / "log.txt"), 0) << bad;
    const std::string log = readAll(dir.path() / "log.txt");
    EXPECT_FALSE(log.empty()) << bad;
  }
  EXPECT_NE(runCli("synth --frames 3", dir.path() / "log.txt"), 0) << "--out is required";
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "sequence" / "rgb.txt"));
}

}  // namespace
}  // namespace segslam::synth
