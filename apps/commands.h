#pragma once

#include <CLI/CLI.hpp>

// Each sub-command of the `segslam` CLI registers itself on the top-level app. The command files
// only parse options and call into the library.
namespace segslam::apps {

void registerRunCommand(CLI::App& app);
void registerCheckCommand(CLI::App& app);
void registerEvalCommand(CLI::App& app);
// `eval masks`, a sub-command of `eval`.
void registerEvalMasksCommand(CLI::App& eval);
// `eval loops`, a sub-command of `eval`.
void registerEvalLoopsCommand(CLI::App& eval);
// `eval map`, a sub-command of `eval`.
void registerEvalMapCommand(CLI::App& eval);
void registerMapCommand(CLI::App& app);
void registerSynthCommand(CLI::App& app);
void registerViewCommand(CLI::App& app);
// `vocab train` and `vocab info`: the bag-of-words vocabulary.
void registerVocabCommand(CLI::App& app);

}  // namespace segslam::apps
