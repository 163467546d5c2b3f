#include "segslam/dense/ply_io.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::dense {
namespace {

using testing::ScopedTempDir;

LabelledCloud threePoints() {
  LabelledCloud cloud;
  cloud.add({1.0f, 2.0f, 3.0f}, {255, 0, 10});
  cloud.add({-0.5f, 0.25f, 1e-3f}, {0, 128, 255});
  cloud.add({1e6f, -1e-6f, 0.0f}, {7, 8, 9});
  return cloud;
}

std::string errorOf(const std::filesystem::path& file) {
  try {
    (void)readPly(file);
  } catch (const util::Error& e) {
    return e.what();
  }
  return "";
}

TEST(PlyIo, RoundTripKeepsPointsAndColours) {
  const ScopedTempDir dir;
  const auto file = dir.path() / "sub" / "cloud.ply";
  writePly(file, threePoints());
  const auto cloud = readPly(file);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.points, threePoints().points);
  EXPECT_EQ(cloud.colours, threePoints().colours);
}

TEST(PlyIo, EmptyCloudRoundTrips) {
  const ScopedTempDir dir;
  writePly(dir.path() / "empty.ply", {});
  EXPECT_TRUE(readPly(dir.path() / "empty.ply").empty());
}

TEST(PlyIo, TruncatedFileNamesTheFile) {
  const ScopedTempDir dir;
  const auto file = dir.path() / "cut.ply";
  writePly(file, threePoints());
  std::filesystem::resize_file(file, std::filesystem::file_size(file) - 4);
  const auto message = errorOf(file);
  EXPECT_NE(message.find("cut.ply"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(PlyIo, CorruptHeadersAreErrors) {
  const ScopedTempDir dir;
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir.path() / name, std::ios::binary) << text;
    return dir.path() / name;
  };
  EXPECT_NE(errorOf(write("magic.ply", "plx\n")).find("magic.ply:1: not a PLY"), std::string::npos);
  EXPECT_NE(errorOf(write("ascii.ply", "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n"))
                .find("ascii.ply:2: unsupported PLY format 'ascii'"),
            std::string::npos);
  EXPECT_NE(errorOf(write("short.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"))
                .find("header ends early"),
            std::string::npos);
  EXPECT_NE(errorOf(write("noxyz.ply",
                          "ply\nformat binary_little_endian 1.0\nelement vertex 0\n"
                          "property float x\nend_header\n"))
                .find("lack x, y or z"),
            std::string::npos);
  EXPECT_NE(errorOf(dir.path() / "missing.ply").find("missing.ply: cannot open"),
            std::string::npos);
}

}  // namespace
}  // namespace segslam::dense
