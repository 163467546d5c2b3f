#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>

#include "segslam/segmentation/mask_propagator.h"
#include "segslam/segmentation/semantic_segmenter.h"

namespace segslam::segmentation {

struct MaskStreamOptions {
  // Runs the network on the calling thread every `interval`-th frame: slower, reproducible.
  // Otherwise the network runs on its own thread whenever it is free (newest frame wins).
  bool synchronous = false;
  int interval = 5;
  // A mask carried over from an older frame grows by this much per frame of age (pixels).
  int growth_px_per_frame = 4;
  int max_growth_px = 40;
};

// Semantic masks for every frame without waiting for the network: the newest finished network
// output is carried to the current frame by optical flow (MaskPropagator). The network runs on
// its own thread (one frame in flight), so a 150-200 ms network does not stall 30 Hz tracking.
// Only the first frame waits for its own output, so that the map never starts on people.
class SemanticMaskStream {
 public:
  SemanticMaskStream(SemanticSegmenter segmenter, MaskStreamOptions options = {});
  ~SemanticMaskStream();
  SemanticMaskStream(const SemanticMaskStream&) = delete;
  SemanticMaskStream& operator=(const SemanticMaskStream&) = delete;

  // Masks for this frame (frames in increasing id order, CV_8UC3 BGR).
  SemanticMasks masksFor(std::uint64_t frame_id, const cv::Mat& bgr);

  // Network runs finished so far and their mean time.
  [[nodiscard]] int networkRuns() const;
  [[nodiscard]] double meanNetworkMilliseconds() const;

 private:
  struct Result {
    std::uint64_t frame_id;
    cv::Mat labels;
  };

  void work();
  void submit(std::uint64_t frame_id, const cv::Mat& bgr);
  void segmentNow(std::uint64_t frame_id, const cv::Mat& bgr);
  [[nodiscard]] SemanticMasks masksFromLabels(const cv::Mat& labels) const;
  void growWithAge(cv::Mat& dynamic, std::uint64_t age) const;

  SemanticSegmenter segmenter_;
  MaskStreamOptions options_;
  std::vector<int> dynamic_indices_;
  MaskPropagator propagator_;
  std::optional<Result> latest_;  // newest output, on the caller's side

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<std::pair<std::uint64_t, cv::Mat>> pending_;  // frame waiting for the network
  std::optional<Result> finished_;                            // output not yet collected
  bool busy_ = false;
  bool stopping_ = false;
  int runs_ = 0;
  double total_ms_ = 0.0;
  std::thread thread_;
};

}  // namespace segslam::segmentation
