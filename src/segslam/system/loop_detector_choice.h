#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "segslam/system/slam_system.h"

namespace segslam::system {

// The loop candidates `segslam run` uses when none are asked for: the CNN descriptor with the
// union mask ("cnn") when the backbone of `backbone_config` is found, else bag of words ("bow").
// That is the rule (CNN + union mask when a backbone is configured); its descriptor
// has the best mean union-mask AUC (bench/results/loops.md) and it corrects the drifting
// synthetic laps as well as bag of words (bench/results/loop_closure.md). A backbone named in
// `backbone_model` counts as found (loading it reports what is wrong with it); a broken backbone
// config is an error, not a fallback. The choice is logged, the fallback as a warning.
struct AutomaticLoopDetector {
  std::string detector;  // "cnn" or "bow"
  std::string reason;    // which backbone was found, or why none was
};
AutomaticLoopDetector automaticLoopDetector(
    const std::filesystem::path& backbone_config,
    const std::optional<std::filesystem::path>& backbone_model);

// The names a caller may ask for: auto, bow, vote, cnn.
const std::vector<std::string>& loopDetectorNames();

// What `segslam run` and the Python System are asked for: loop closing, its candidates, the
// vocabulary (relocalisation, and the bow detector's words) and the CNN backbone.
struct LoopDetectionRequest {
  bool loop_closing = true;
  std::string detector = "auto";  // one of loopDetectorNames()
  std::filesystem::path vocabulary;
  // The vocabulary shipped in config/, the only one that may be missing (a checkout without
  // config/): relocalisation then tries the most recent keyframes only, and the bow detector
  // falls back to the descriptor vote. A vocabulary the caller names must load.
  std::filesystem::path shipped_vocabulary;
  std::filesystem::path backbone_config;
  std::optional<std::filesystem::path> backbone_model;
};

struct LoopDetection {
  std::string detector;                   // "auto" resolved; "none" without loop closing
  std::filesystem::path vocabulary_file;  // the vocabulary loaded (empty: none)
};

// Resolves "auto" (automaticLoopDetector), loads the vocabulary and, for the cnn
// detector, the backbone into `slam`. Throws util::Error for an unknown detector, or a named
// vocabulary or backbone that does not load.
LoopDetection configureLoopDetection(const LoopDetectionRequest& request, SlamOptions& slam);

}  // namespace segslam::system
