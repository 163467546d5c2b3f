#include "segslam/viewer/served_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"

namespace segslam::viewer {
namespace {

namespace fs = std::filesystem;

class ServedFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(run() / "map");
    std::ofstream(run() / "map" / "static.ply") << "ply";
    std::ofstream(run() / "index.html") << "page";
    std::ofstream(dir_.path() / "secret.txt") << "secret";
  }
  fs::path run() const { return dir_.path() / "run"; }
  ServedFolder served() const { return {"/run/", run()}; }

  testing::ScopedTempDir dir_;
};

TEST_F(ServedFileTest, ServesRegularFilesInsideTheFolder) {
  EXPECT_TRUE(mayServe(served(), "/run/map/static.ply"));
  EXPECT_TRUE(mayServe(served(), "/run/"));            // its index.html
  EXPECT_TRUE(mayServe(served(), "/run/absent.txt"));  // the server's 404
  EXPECT_TRUE(mayServe(served(), "/api/run"));         // not under the prefix
}

TEST_F(ServedFileTest, RefusesLinksOutAndPathsThatClimbOut) {
  fs::create_symlink(dir_.path() / "secret.txt", run() / "escape.txt");
  fs::create_symlink("/", run() / "root");
  fs::create_symlink(dir_.path() / "absent", run() / "dangling");
  EXPECT_FALSE(mayServe(served(), "/run/escape.txt"));
  EXPECT_FALSE(mayServe(served(), "/run/root/etc/passwd"));
  EXPECT_FALSE(mayServe(served(), "/run/root"));
  EXPECT_FALSE(mayServe(served(), "/run/dangling"));
  EXPECT_FALSE(mayServe(served(), "/run/../secret.txt"));
  EXPECT_FALSE(mayServe(served(), "/run/map"));  // a folder, not a file
}

TEST_F(ServedFileTest, FollowsLinksThatStayInside) {
  fs::create_symlink(run() / "map" / "static.ply", run() / "cloud.ply");
  EXPECT_TRUE(mayServe(served(), "/run/cloud.ply"));
}

}  // namespace
}  // namespace segslam::viewer
