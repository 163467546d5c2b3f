#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "segslam/feature/feature_test_images.h"
#include "segslam/testing/test_support.h"

namespace segslam::place {
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
  std::ifstream in(file, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

TEST(VocabCli, TrainsAndDescribesAVocabulary) {
  const ScopedTempDir dir;
  const auto images = dir.path() / "images";
  std::filesystem::create_directories(images);
  for (int i = 0; i < 4; ++i) {
    cv::imwrite((images / ("frame_" + std::to_string(i) + ".png")).string(),
                feature::testing::texturedImage({200, 150}, static_cast<std::uint64_t>(i), 300));
  }
  const auto file = dir.path() / "test.voc";
  const auto log = dir.path() / "log.txt";
  ASSERT_EQ(runCli("vocab train --images '" + images.string() + "' --out '" + file.string() +
                       "' --k 4 --depth 3 --every 1 --features 300",
                   log),
            0)
      << readAll(log);
  ASSERT_EQ(runCli("vocab info '" + file.string() + "'", log), 0) << readAll(log);
  const std::string info = readAll(log);
  EXPECT_NE(info.find("k 4, depth 3"), std::string::npos) << info;
  EXPECT_NE(info.find("4 images"), std::string::npos) << info;
  EXPECT_NE(info.find("images:images"), std::string::npos) << info;
}

TEST(VocabCli, CorruptFileIsAnErrorNamingIt) {
  const ScopedTempDir dir;
  const auto file = dir.path() / "corrupt.voc";
  std::ofstream(file, std::ios::binary) << "SEGSBOWV";
  const auto log = dir.path() / "log.txt";
  EXPECT_EQ(runCli("vocab info '" + file.string() + "'", log), 1);
  const std::string message = readAll(log);
  EXPECT_NE(message.find("error: " + file.string()), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

}  // namespace
}  // namespace segslam::place
