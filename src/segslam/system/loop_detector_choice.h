#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace segslam::system {

// The loop candidates `segslam run` uses when none are asked for: the CNN descriptor with the
// union mask ("cnn") when the backbone of `backbone_config` is found, else bag of words ("bow").
// That is the rule (CNN + union mask when a backbone is configured); its descriptor
// has the best mean union-mask AUC (bench/results/loops.md) and it corrects the drifting
// synthetic laps as well as bag of words (bench/results/loop_closure.md). A backbone named in
// `backbone_model` counts as found (loading it reports what is wrong with it); a broken backbone
// config is an error, not a fallback.
struct AutomaticLoopDetector {
  std::string detector;  // "cnn" or "bow"
  std::string reason;    // which backbone was found, or why none was
};
AutomaticLoopDetector automaticLoopDetector(
    const std::filesystem::path& backbone_config,
    const std::optional<std::filesystem::path>& backbone_model);

}  // namespace segslam::system
