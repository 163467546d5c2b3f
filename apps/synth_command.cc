#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <memory>

#include "commands.h"
#include "segslam/synth/generator.h"
#include "segslam/util/output_folder.h"
#include "segslam/util/progress.h"

namespace segslam::apps {

namespace {

struct SynthArguments {
  std::string out;
  synth::SynthOptions options;
};

void addOptions(CLI::App& command, SynthArguments& args) {
  synth::SynthOptions& o = args.options;
  command.add_option("-o,--out", args.out, "Output folder (TUM RGB-D layout)")->required();
  command.add_option("--frames", o.frames, "Number of frames (30 per second)")
      ->capture_default_str();
  command.add_option("--width", o.width, "Image width in pixels (fx = fy = 525 * width / 640)")
      ->capture_default_str();
  command.add_option("--height", o.height, "Image height in pixels")->capture_default_str();
  command
      .add_option("--path", o.path,
                  "Camera path: xyz (back and forth along the camera axes), loop (one lap that "
                  "ends at its start pose; needs >= 240 frames), room (a lap turning once all the "
                  "way round, ends at its start pose; needs >= 240 frames) or static")
      ->check(CLI::IsMember(synth::cameraPathNames()))
      ->capture_default_str();
  command.add_option("--laps", o.laps, "Laps of the loop or room path (>= 240 frames each)")
      ->check(CLI::Range(1, synth::kSynthMaxLaps))
      ->capture_default_str();
  command.add_option("--people", o.people, "Number of walking people (0 = static scene)")
      ->check(CLI::Range(0, synth::kSynthMaxPeople))
      ->capture_default_str();
  command.add_option("--person-speed", o.person_speed, "Walking speed in m/s, 0-3 (0 = standing)")
      ->capture_default_str();
  command.add_option("--person-size", o.person_size, "Scale of a 1.75 m tall person, 0.5-1.4")
      ->capture_default_str();
  command.add_flag("--moved-furniture", o.moved_furniture,
                   "Push a chair 0.55 m across the floor during 30-55 % of the sequence");
  command
      .add_option("--depth-noise", o.depth_noise,
                  "Depth noise: none (exact z, quantised) or kinect (noise growing with z, holes "
                  "below 0.4 m, beyond 8 m and at depth edges)")
      ->check(CLI::IsMember(synth::depthNoiseNames()))
      ->capture_default_str();
  command.add_option("--seed", o.seed, "Seed of all randomness (textures, layout, people, noise)")
      ->capture_default_str();
}

void logSummary(const synth::SynthSummary& summary) {
  const double frames = std::max(summary.frames, 1);
  spdlog::info("wrote {} frames to {}", summary.frames, summary.folder.string());
  spdlog::info(
      "time {:.2f} s ({:.1f} frames/s; setup {:.2f} s, per frame {:.1f} ms rendering, "
      "{:.1f} ms writing, overlapped)",
      summary.seconds, summary.frames / std::max(summary.seconds, 1e-9), summary.setup_seconds,
      1000.0 * summary.render_seconds / frames, 1000.0 * summary.write_seconds / frames);
  spdlog::info("a person is visible in {} of {} frames ({:.0f} %)", summary.frames_with_person,
               summary.frames, 100.0 * summary.frames_with_person / frames);
  spdlog::info("dynamic pixels per frame: mean {:.1f} %, max {:.1f} %",
               100.0 * summary.mean_dynamic_share, 100.0 * summary.max_dynamic_share);
}

void runSynth(const SynthArguments& args) {
  const synth::SynthOptions& o = args.options;
  synth::validateOptions(o);  // before the progress bar starts drawing
  util::createOutputFolder(args.out);
  spdlog::info(
      "synth: {} frames {}x{}, path {} ({} laps), {} people at {} m/s, moved furniture {}, "
      "depth noise {}, seed {}",
      o.frames, o.width, o.height, o.path, o.laps, o.people, o.person_speed,
      o.moved_furniture ? "on" : "off", o.depth_noise, o.seed);
  util::ProgressBar bar("synth", static_cast<std::size_t>(o.frames));
  const auto summary = synth::generateSequence(o, args.out, [&](int, int) { bar.advance(); });
  bar.finish();
  logSummary(summary);
}

}  // namespace

void registerSynthCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "synth",
      "Render a synthetic dynamic RGB-D sequence (textured room, walking people) with "
      "exact ground truth, in the TUM RGB-D layout");
  auto args = std::make_shared<SynthArguments>();
  addOptions(*command, *args);
  command->callback([args] { runSynth(*args); });
}

}  // namespace segslam::apps
