#include "commands.h"

namespace segslam::apps {

void registerEvalCommand(CLI::App& app) {
  app.add_subcommand("eval", "placeholder, being written");
}

}  // namespace segslam::apps
