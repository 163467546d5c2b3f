#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>

#include "segslam/synth/synth_options.h"

namespace segslam::synth {

struct SynthSummary {
  std::filesystem::path folder;
  int frames = 0;
  std::size_t objects = 0;
  double seconds = 0.0;             // wall time of the whole generation
  double setup_seconds = 0.0;       // building the scene and painting its textures
  double render_seconds = 0.0;      // rendering, summed over frames
  double write_seconds = 0.0;       // PNG encoding and writing, summed over frames
  int frames_with_person = 0;       // frames that show at least one person pixel
  double mean_dynamic_share = 0.0;  // mean fraction of mask (dynamic) pixels per frame
  double max_dynamic_share = 0.0;
};

// Called after each finished frame, in frame order, from one thread at a time.
using ProgressCallback = std::function<void(int frames_done, int frames_total)>;

// Renders the sequence described by `options` and writes it to `out_dir` in the TUM RGB-D layout
// with exact ground truth (see SequenceWriter for the files). The masks mark the objects that are
// dynamic at each frame: those whose world pose differs from the previous or next frame (see
// Scene). Rendering of one frame overlaps the
// writing of the previous ones. Throws util::Error for invalid options or unwritable files.
SynthSummary generateSequence(const SynthOptions& options, const std::filesystem::path& out_dir,
                              const ProgressCallback& progress = {});

}  // namespace segslam::synth
