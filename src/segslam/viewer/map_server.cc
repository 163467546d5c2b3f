#include "segslam/viewer/map_server.h"

#include <fmt/format.h>
#include <httplib.h>

#include "segslam/util/error.h"
#include "segslam/viewer/run_contents.h"
#include "segslam/viewer/served_file.h"

namespace segslam::viewer {

namespace {

namespace fs = std::filesystem;

constexpr const char* kRunPrefix = "/run/";

void requireWebBuild(const fs::path& web_dir) {
  if (!fs::is_regular_file(web_dir / "index.html")) {
    util::failAt(web_dir / "index.html",
                 "viewer front end not built (run scripts/build_web.sh, or pass --web-dir)");
  }
}

void answerRunDescription(const fs::path& run_dir, httplib::Response& response) {
  try {
    response.set_content(runContentsJson(describeRun(run_dir), kRunPrefix).dump(),
                         "application/json");
  } catch (const util::Error& e) {
    response.status = 500;
    response.set_content(nlohmann::json{{"error", e.what()}}.dump(), "application/json");
  }
}

}  // namespace

MapServer::MapServer(MapServerOptions options)
    : options_(std::move(options)), server_(std::make_unique<httplib::Server>()) {
  describeRun(options_.run_dir);
  requireWebBuild(options_.web_dir);
  addRoutes();
}

MapServer::~MapServer() = default;

void MapServer::addRoutes() {
  // httplib's mount points refuse paths that climb out of the folder ("..").
  server_->set_mount_point(kRunPrefix, options_.run_dir.string());
  server_->set_mount_point("/", options_.web_dir.string());
  // The mount points follow links: one in the run folder to /etc/passwd would be served.
  server_->set_pre_routing_handler(
      [run_dir = options_.run_dir, web_dir = options_.web_dir](const httplib::Request& request,
                                                               httplib::Response& response) {
        const bool in_run = request.path.starts_with(kRunPrefix);
        const ServedFolder served =
            in_run ? ServedFolder{kRunPrefix, run_dir} : ServedFolder{"/", web_dir};
        if (mayServe(served, request.path)) return httplib::Server::HandlerResponse::Unhandled;
        response.status = 404;
        return httplib::Server::HandlerResponse::Handled;
      });
  // httplib compresses text/* and application/javascript bodies with Brotli at its slowest
  // setting, seconds for the 0.6 MB bundle; these types are valid for the page but not compressed.
  server_->set_file_extension_and_mimetype_mapping("js", "application/x-javascript");
  server_->set_file_extension_and_mimetype_mapping("ply", "application/octet-stream");
  server_->set_file_extension_and_mimetype_mapping("txt", "application/octet-stream");
  server_->set_file_extension_and_mimetype_mapping("pgm", "image/x-portable-graymap");
  server_->Get("/api/run",
               [run_dir = options_.run_dir](const httplib::Request&, httplib::Response& response) {
                 answerRunDescription(run_dir, response);
               });
}

int MapServer::bind() {
  if (options_.port == 0) {
    port_ = server_->bind_to_any_port(options_.host);
  } else if (server_->bind_to_port(options_.host, options_.port)) {
    port_ = options_.port;
  }
  if (port_ < 0) {
    throw util::Error(
        fmt::format("cannot listen on {}:{} (in use? try --port 0)", options_.host, options_.port));
  }
  return port_;
}

void MapServer::serve() { server_->listen_after_bind(); }

void MapServer::stop() { server_->stop(); }

std::string MapServer::url() const { return fmt::format("http://{}:{}/", options_.host, port_); }

}  // namespace segslam::viewer
