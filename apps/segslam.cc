#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <exception>

#include "commands.h"
#include "segslam/util/error.h"
#include "segslam/util/heap_retention.h"
#include "segslam/util/logging.h"

int main(int argc, char** argv) {
  segslam::util::boundHeapRetention();
  const segslam::util::HeapTrimmer heap_trimmer;
  CLI::App app{"segslam: RGB-D SLAM for dynamic scenes", "segslam"};
  app.set_version_flag("--version", SEGSLAM_VERSION);
  app.require_subcommand(1);
  std::string log_level = "info";
  app.add_option("--log-level", log_level, "Console log level")
      ->check(CLI::IsMember(segslam::util::logLevelNames()))
      ->capture_default_str();
  app.parse_complete_callback([&] { segslam::util::setupLogging(log_level); });

  segslam::apps::registerRunCommand(app);
  segslam::apps::registerCheckCommand(app);
  segslam::apps::registerEvalCommand(app);
  segslam::apps::registerSynthCommand(app);
  segslam::apps::registerViewCommand(app);
  segslam::apps::registerVocabCommand(app);
  segslam::apps::registerMapCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const segslam::util::Error& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: internal failure: {}\n", e.what());
    return 1;
  }
  return 0;
}
