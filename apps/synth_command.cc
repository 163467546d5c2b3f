#include "commands.h"

namespace segslam::apps {

void registerSynthCommand(CLI::App& app) {
  app.add_subcommand("synth", "placeholder, being written");
}

}  // namespace segslam::apps
