#include "segslam/util/logging.h"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace segslam::util {

std::vector<std::string> logLevelNames() {
  return {"trace", "debug", "info", "warn", "error", "off"};
}

void setupLogging(const std::string& level) {
  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  console->set_level(spdlog::level::from_str(level));
  console->set_pattern("[%l] %v");
  auto logger = std::make_shared<spdlog::logger>("segslam", console);
  logger->set_level(spdlog::level::trace);
  spdlog::set_default_logger(logger);
}

void addLogFile(const std::filesystem::path& file) {
  auto sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>(file.string(), true);
  sink->set_level(spdlog::level::debug);
  sink->set_pattern("%Y-%m-%d %H:%M:%S.%e [%l] %v");
  spdlog::default_logger()->sinks().push_back(sink);
}

}  // namespace segslam::util
