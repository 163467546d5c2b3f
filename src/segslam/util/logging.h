#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace segslam::util {

// Levels a user can pick on the command line.
std::vector<std::string> logLevelNames();

// Configures the default spdlog logger: colour console output on stderr at `level`
// ("trace", "debug", "info", "warn", "error", "off").
void setupLogging(const std::string& level);

// Adds a file sink (all levels from debug up) so a run keeps its log in its output folder.
void addLogFile(const std::filesystem::path& file);

}  // namespace segslam::util
