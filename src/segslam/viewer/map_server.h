#pragma once

#include <filesystem>
#include <memory>
#include <string>

namespace httplib {
class Server;
}

namespace segslam::viewer {

struct MapServerOptions {
  std::filesystem::path run_dir;  // a `segslam run` output folder
  std::filesystem::path web_dir;  // the built front end (web/dist)
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port
};

// Serves the viewer page from `web_dir`, the run folder's files under /run/ and a description of
// the run (what trajectories and map files exist, the objects index) at /api/run.
class MapServer {
 public:
  // Throws util::Error when the run folder or the web build is missing, or the run's map index
  // is malformed.
  explicit MapServer(MapServerOptions options);
  ~MapServer();
  MapServer(const MapServer&) = delete;
  MapServer& operator=(const MapServer&) = delete;

  // Binds the listening socket and returns its port; throws util::Error when that fails.
  int bind();
  // Answers requests until stop() is called; call bind() first.
  void serve();
  // Safe from any thread.
  void stop();

  [[nodiscard]] std::string url() const;

 private:
  void addRoutes();

  MapServerOptions options_;
  std::unique_ptr<httplib::Server> server_;
  int port_ = -1;
};

}  // namespace segslam::viewer
