#include "segslam/synth/generator.h"

#include <tbb/parallel_pipeline.h>

#include <algorithm>
#include <chrono>
#include <opencv2/core.hpp>

#include "segslam/synth/sequence.h"
#include "segslam/synth/sequence_writer.h"

namespace segslam::synth {

namespace {

// Frames in flight: one being rendered, the others being written.
constexpr std::size_t kFramesInFlight = 4;

class Stopwatch {
 public:
  [[nodiscard]] double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

struct RenderedFrame {
  int index = -1;
  FrameImages images;
  double render_seconds = 0.0;
};

struct FrameStats {
  double render_seconds = 0.0;
  double write_seconds = 0.0;
  bool person_visible = false;
  double dynamic_share = 0.0;
};

FrameStats measure(const RenderedFrame& frame) {
  FrameStats stats;
  stats.render_seconds = frame.render_seconds;
  const cv::Mat& labels = frame.images.labels;
  stats.person_visible =
      cv::countNonZero(labels == static_cast<int>(core::SemanticClass::kPerson)) > 0;
  stats.dynamic_share = static_cast<double>(cv::countNonZero(frame.images.mask)) /
                        static_cast<double>(frame.images.mask.total());
  return stats;
}

void accumulate(const FrameStats& stats, SynthSummary& summary) {
  summary.render_seconds += stats.render_seconds;
  summary.write_seconds += stats.write_seconds;
  if (stats.person_visible) ++summary.frames_with_person;
  summary.mean_dynamic_share += stats.dynamic_share;
  summary.max_dynamic_share = std::max(summary.max_dynamic_share, stats.dynamic_share);
}

}  // namespace

SynthSummary generateSequence(const SynthOptions& options, const std::filesystem::path& out_dir,
                              const ProgressCallback& progress) {
  const Stopwatch total;
  const SyntheticSequence sequence(options);
  const SequenceWriter writer(out_dir);
  SynthSummary summary;
  summary.folder = out_dir;
  summary.frames = sequence.frameCount();
  summary.objects = sequence.scene().objects().size();
  summary.setup_seconds = total.seconds();

  int next_frame = 0;
  int frames_done = 0;
  tbb::parallel_pipeline(
      kFramesInFlight, tbb::make_filter<void, RenderedFrame>(
                           tbb::filter_mode::serial_in_order,
                           [&](tbb::flow_control& control) {
                             if (next_frame >= sequence.frameCount()) {
                               control.stop();
                               return RenderedFrame{};
                             }
                             const Stopwatch watch;
                             RenderedFrame frame{next_frame, sequence.renderFrame(next_frame), 0.0};
                             frame.render_seconds = watch.seconds();
                             ++next_frame;
                             return frame;
                           }) &
                           tbb::make_filter<RenderedFrame, FrameStats>(
                               tbb::filter_mode::parallel,
                               [&](const RenderedFrame& frame) {
                                 FrameStats stats = measure(frame);
                                 const Stopwatch watch;
                                 writer.writeFrame(sequence, frame.index, frame.images);
                                 stats.write_seconds = watch.seconds();
                                 return stats;
                               }) &
                           tbb::make_filter<FrameStats, void>(
                               tbb::filter_mode::serial_in_order, [&](const FrameStats& stats) {
                                 accumulate(stats, summary);
                                 if (progress) progress(++frames_done, summary.frames);
                               }));
  writer.writeMetadata(sequence);
  summary.mean_dynamic_share /= std::max(summary.frames, 1);
  summary.seconds = total.seconds();
  return summary;
}

}  // namespace segslam::synth
