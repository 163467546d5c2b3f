#include "segslam/viewer/map_server.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"
#include "segslam/viewer/test_run_folder.h"

namespace segslam::viewer {
namespace {

using testing::ScopedTempDir;

// A server on a free port over a fixture run folder and a one-file web build, answering on a
// background thread for the test's lifetime.
class ViewerMapServer : public ::testing::Test {
 protected:
  void SetUp() override {
    fixtures::writeRunFolder(dir_.path() / "run", /*with_map=*/true);
    std::filesystem::create_directories(dir_.path() / "web");
    std::ofstream(dir_.path() / "web" / "index.html") << "<html>viewer</html>";
    server_ = std::make_unique<MapServer>(
        MapServerOptions{dir_.path() / "run", dir_.path() / "web", "127.0.0.1", 0});
    port_ = server_->bind();
    thread_ = std::thread([this] { server_->serve(); });
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
  }

  // Every test has made a request by now, so the accept loop is running and stop() ends it.
  void TearDown() override {
    server_->stop();
    thread_.join();
  }

  ScopedTempDir dir_;
  std::unique_ptr<MapServer> server_;
  std::thread thread_;
  int port_ = 0;
  std::unique_ptr<httplib::Client> client_;
};

TEST_F(ViewerMapServer, DescribesTheRun) {
  EXPECT_GT(port_, 0);
  const auto response = client_->Get("/api/run");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  const auto json = nlohmann::json::parse(response->body);
  EXPECT_EQ(json["name"], "run");
  EXPECT_EQ(json["trajectories"]["keyframes"], "/run/KeyFrameTrajectory.txt");
  EXPECT_EQ(json["map"]["objects"].size(), 3u);
}

TEST_F(ViewerMapServer, ServesThePageAndRunFiles) {
  const auto page = client_->Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_EQ(page->body, "<html>viewer</html>");
  const auto cloud = client_->Get("/run/map/static.ply");
  ASSERT_TRUE(cloud);
  EXPECT_EQ(cloud->status, 200);
  EXPECT_EQ(cloud->body,
            segslam::testing::fileContents(dir_.path() / "run" / "map" / "static.ply"));
  const auto trajectory = client_->Get("/run/CameraTrajectory.txt");
  ASSERT_TRUE(trajectory);
  EXPECT_EQ(trajectory->body,
            segslam::testing::fileContents(dir_.path() / "run" / "CameraTrajectory.txt"));
}

TEST_F(ViewerMapServer, SendsTheBundleUncompressedAsJavaScript) {
  std::ofstream(dir_.path() / "web" / "viewer.js") << std::string(4096, ';');
  const auto response = client_->Get("/viewer.js", {{"Accept-Encoding", "gzip, deflate, br"}});
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  EXPECT_FALSE(response->has_header("Content-Encoding"));
  EXPECT_NE(response->get_header_value("Content-Type").find("javascript"), std::string::npos);
  EXPECT_EQ(response->body.size(), 4096u);
}

TEST_F(ViewerMapServer, RefusesPathsOutsideTheServedFolders) {
  std::ofstream(dir_.path() / "secret.txt") << "secret";
  for (const char* path : {"/run/../secret.txt", "/run/../../etc/passwd", "/../secret.txt",
                           "/run/%2e%2e/secret.txt", "/run/map/../../secret.txt"}) {
    const auto response = client_->Get(path);
    ASSERT_TRUE(response) << path;
    EXPECT_NE(response->status, 200) << path;
    EXPECT_EQ(response->body.find("secret"), std::string::npos) << path;
    EXPECT_EQ(response->body.find("root:"), std::string::npos) << path;
  }
}

TEST_F(ViewerMapServer, RefusesLinksOutOfTheServedFolders) {
  std::ofstream(dir_.path() / "secret.txt") << "secret";
  std::filesystem::create_directories(dir_.path() / "outside");
  std::ofstream(dir_.path() / "outside" / "index.html") << "secret";
  const auto run = dir_.path() / "run";
  std::filesystem::create_symlink(dir_.path() / "secret.txt", run / "escape.txt");
  std::filesystem::create_symlink("/", run / "root");
  std::filesystem::create_directory_symlink(dir_.path() / "outside", run / "outside");
  std::filesystem::create_symlink(dir_.path() / "secret.txt", dir_.path() / "web" / "escape.js");
  std::filesystem::create_symlink(run / "CameraTrajectory.txt", run / "inside.txt");
  for (const char* path : {"/run/escape.txt", "/run/root/etc/passwd", "/run/outside/",
                           "/run/outside/index.html", "/escape.js", "/run/root/"}) {
    const auto response = client_->Get(path);
    ASSERT_TRUE(response) << path;
    EXPECT_EQ(response->status, 404) << path;
    EXPECT_EQ(response->body.find("secret"), std::string::npos) << path;
    EXPECT_EQ(response->body.find("root:"), std::string::npos) << path;
  }
  const auto inside = client_->Get("/run/inside.txt");
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->status, 200);
  EXPECT_EQ(inside->body, segslam::testing::fileContents(run / "CameraTrajectory.txt"));
}

TEST(ViewerMapServerSetup, MissingRunFolderOrWebBuildIsAnError) {
  const ScopedTempDir dir;
  fixtures::writeRunFolder(dir.path() / "run", /*with_map=*/false);
  std::filesystem::create_directories(dir.path() / "web");
  try {
    MapServer server({dir.path() / "run", dir.path() / "web", "127.0.0.1", 0});
    ADD_FAILURE() << "accepted a web folder without index.html";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("build_web.sh"), std::string::npos) << e.what();
  }
  std::ofstream(dir.path() / "web" / "index.html") << "<html></html>";
  EXPECT_THROW(MapServer({dir.path() / "absent", dir.path() / "web", "127.0.0.1", 0}), util::Error);
  EXPECT_NO_THROW(MapServer({dir.path() / "run", dir.path() / "web", "127.0.0.1", 0}));
}

}  // namespace
}  // namespace segslam::viewer
