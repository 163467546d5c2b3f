#include "commands.h"

namespace segslam::apps {

void registerRunCommand(CLI::App& app) {
  app.add_subcommand("run", "placeholder, being written");
}

}  // namespace segslam::apps
