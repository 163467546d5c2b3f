// Speed of the synthetic sequence generator: renders and writes the default sequence (300 frames,
// 640x480, two walking people, xyz path) with all threads, as `segslam synth` does.
//
//   segslam_bench_synth_render [results.json] [sequence folder]
//
// Without a sequence folder it writes into a temporary folder that is removed afterwards.
// Rendering of a frame overlaps the PNG writing of earlier ones, so the per-frame render and
// write times add up to more than the total.

#include <fmt/format.h>
#include <tbb/info.h>

#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <string>

#include "segslam/synth/generator.h"

namespace {

namespace fs = std::filesystem;

// A fresh folder under the system temp folder, removed when the object goes away.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    path_ =
        fs::temp_directory_path() / fmt::format("segslam_bench_synth_{}", std::random_device{}());
    fs::create_directories(path_);
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// CPU seconds of the whole process (all threads): comparable even on a busy machine.
double processCpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

nlohmann::json resultsJson(const segslam::synth::SynthSummary& summary, double cpu_seconds) {
  const double frames = summary.frames;
  return {{"benchmark", "synth_render"},
          {"frames", summary.frames},
          {"width", 640},
          {"height", 480},
          {"threads", tbb::info::default_concurrency()},
          {"total_seconds", summary.seconds},
          {"cpu_seconds", cpu_seconds},
          {"frames_per_second", frames / summary.seconds},
          {"setup_seconds", summary.setup_seconds},
          {"render_ms_per_frame", 1000.0 * summary.render_seconds / frames},
          {"write_ms_per_frame", 1000.0 * summary.write_seconds / frames},
          {"frames_with_person", summary.frames_with_person},
          {"mean_dynamic_share", summary.mean_dynamic_share}};
}

void printResults(const segslam::synth::SynthSummary& summary, double cpu_seconds) {
  const double frames = summary.frames;
  fmt::print("synth_render: {} frames 640x480 with {} threads\n", summary.frames,
             tbb::info::default_concurrency());
  fmt::print("  total          {:8.2f} s  ({:.1f} frames/s)\n", summary.seconds,
             frames / summary.seconds);
  fmt::print("  cpu time       {:8.2f} s  (all threads)\n", cpu_seconds);
  fmt::print("  setup          {:8.2f} s  (scene and textures)\n", summary.setup_seconds);
  fmt::print("  render         {:8.2f} ms per frame\n", 1000.0 * summary.render_seconds / frames);
  fmt::print("  write (PNG)    {:8.2f} ms per frame\n", 1000.0 * summary.write_seconds / frames);
  fmt::print("  person visible in {} frames, mean dynamic share {:.1f} %\n",
             summary.frames_with_person, 100.0 * summary.mean_dynamic_share);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const fs::path results = argc > 1 ? fs::path(argv[1]) : fs::path();
    TemporaryFolder temporary;
    const fs::path folder = argc > 2 ? fs::path(argv[2]) : temporary.path() / "sequence";
    const double cpu_start = processCpuSeconds();
    const auto summary = segslam::synth::generateSequence(segslam::synth::SynthOptions{}, folder);
    const double cpu_seconds = processCpuSeconds() - cpu_start;
    printResults(summary, cpu_seconds);
    if (!results.empty()) {
      std::ofstream out(results);
      out << resultsJson(summary, cpu_seconds).dump(2) << "\n";
      if (!out) throw std::runtime_error("cannot write " + results.string());
      fmt::print("  results written to {}\n", results.string());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
