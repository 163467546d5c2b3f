#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.h"
#include "segslam/viewer/map_server.h"

namespace segslam::apps {

void registerViewCommand(CLI::App& app) {
  auto options = std::make_shared<viewer::MapServerOptions>();
  options->web_dir = SEGSLAM_WEB_DIR;
  auto* command = app.add_subcommand(
      "view",
      "Serve an interactive map viewer for a run folder on a local web page: point cloud, "
      "estimated and ground-truth trajectories, keyframes, per-object toggles");
  command->add_option("--run", options->run_dir, "Output folder of `segslam run`")->required();
  command->add_option("--port", options->port, "TCP port (0: any free port)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  command->add_option("--host", options->host, "Address to listen on")->capture_default_str();
  command
      ->add_option("--web-dir", options->web_dir,
                   "Built front end (scripts/build_web.sh writes web/dist)")
      ->capture_default_str();
  command->callback([options] {
    viewer::MapServer server(*options);
    server.bind();
    fmt::print("segslam view: {} at {} (Ctrl-C to stop)\n",
               std::filesystem::absolute(options->run_dir).lexically_normal().string(),
               server.url());
    std::fflush(stdout);
    server.serve();
  });
}

}  // namespace segslam::apps
