#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <vector>

#include "segslam/segmentation/depth_mask_refiner.h"
#include "segslam/segmentation/mask_propagator.h"
#include "segslam/segmentation/semantic_segmenter.h"

namespace segslam::segmentation {

struct MaskStreamOptions {
  // Segments on the calling thread every `interval`-th frame: slower, reproducible. Otherwise the
  // segmenter runs on its own thread whenever it is free (newest frame wins).
  bool synchronous = false;
  int interval = 5;
  // Synchronous mode: an output is used only this many frames after its own frame, as a
  // segmenter on its own thread would deliver it; makes the real-time behaviour reproducible.
  int latency_frames = 0;
  // Lowers the segmentation thread's scheduling priority (nice) so that it takes only the CPU
  // time tracking and mapping leave: a late mask is carried over, a late frame is lost. At 19
  // (the lowest) feature extraction's worker gets the second core back soonest (walker, fast
  // playback, semantic masks: 82 % of the frame rate without masks, against 78 % at nice 10).
  int thread_niceness = 19;
  // While tracking is busy computing (setTrackingBusyShare() at or above `busy_share_limit`:
  // offline playback as fast as frames load), the segmenter thread takes a frame only every
  // `busy_interval` frames, since every run takes CPU that tracking needs (ESPNetv2: 60 ms on 2
  // idle cores, 100-300 ms beside tracking). Tracking that waits for its frames (a camera) leaves
  // CPU to spare: the segmenter then runs whenever it is free. (Walker, fast playback: every 30 /
  // 45 / 60 frames gives 75 / 78 / 81 % of the frame rate without masks; at 60 frames the masks are
  // too stale: ATE 0.107 against 0.023 m.)
  double busy_share_limit = 0.75;
  int busy_interval = 45;
  // A mask carried over from an older frame may have fallen behind its object by this much per
  // frame of age (pixels): the depth refinement searches that far around it (or, without depth,
  // the mask is grown that much).
  int growth_px_per_frame = 4;
  int max_growth_px = 40;
  // Even a fresh output is searched this far around (a network sees a downscaled image).
  int min_band_px = 8;
  // Whether the per-pixel labels are carried along with the dynamic mask; without them (nothing
  // reads them, e.g. no object map is built) masksFor() returns empty labels and saves a remap
  // per frame.
  bool carry_labels = true;
  // Whether a fresh output (age 0) is snapped to depth too; off for outputs already grown over
  // depth (geometric segmentation).
  bool refine_fresh_masks = true;
  // An object that a new output no longer shows, though the frame before had it in its mask, is
  // kept in the masks while it touches the image border, for at most this many frames after an
  // output last showed it: a network does not recognise a person cut down to a strip by the
  // frame's edge (the walker's shirt at the left border, 24 frames). 0 = off.
  int border_linger_frames = 0;
  // Keyframes waiting for the segmenter, at most: when it cannot keep up (a slow machine, a
  // camera carried quickly through new space) the oldest is given up and goes on with its carried
  // mask, so that the queue's images never pile up.
  std::size_t max_queued_keyframes = 4;
  // At the optical flow's half resolution, where carried masks come from: a quarter of the
  // tracking thread's time on the masks.
  DepthRefinementOptions refinement{.downscale = 2};
};

// A frame as the segmenters see it.
struct StreamFrame {
  std::uint64_t id = 0;
  cv::Mat bgr;    // CV_8UC3
  cv::Mat depth;  // CV_32FC1 metres, or empty
};

// What a segmenter is given: the frame, the one before it (empty for the first), and what is
// already known to move in the frame (another method's mask, or empty).
struct SegmentationJob {
  StreamFrame previous;
  StreamFrame current;
  cv::Mat known_dynamic;
};
// An empty `dynamic` mask means the segmenter could not tell (e.g. geometric segmentation that
// found no trustworthy camera motion): the stream goes on carrying its previous output, since an
// object that was moving a moment ago most likely still is. An all-zero mask means nothing moves.
using Segment = std::function<SemanticMasks(const SegmentationJob&)>;

// An output that arrived after its frame had been handed on: the map can still be cleaned of
// what it shows. A keyframe's own output (MaskStream::segmentKeyFrame) tells local mapping which
// of the keyframe's points lie on moving objects; any other tells tracking which recent map
// points do (tracking::pointsOnDynamicSurface).
struct LateOutput {
  std::uint64_t frame_id = 0;
  cv::Mat dynamic;  // CV_8UC1, 255 = dynamic: the segmenter's output, snapped to depth as fresh
  cv::Mat labels;   // CV_8UC1, the segmenter's labels; empty unless carry_labels
  cv::Mat depth;    // CV_32FC1 metres of that frame, or empty
  bool keyframe = false;  // asked for by segmentKeyFrame()
};

// Masks for every frame without waiting for a slow segmenter (a 60-300 ms network, geometric
// segmentation): the newest finished output is carried to the current frame by optical flow
// (MaskPropagator) and snapped to the objects' depth outlines. The segmenter runs on its own
// thread, one frame in flight; keyframes come first (segmentKeyFrame), then the newest frame.
// Only the first frame waits for its own output, so that the map never starts on people.
class MaskStream {
 public:
  // `propagator`: optical flow shared with other streams over the same frames (fused masks
  // carry two segmenters' outputs by the same flow, computed once per frame); null gives the
  // stream its own.
  MaskStream(Segment segment, MaskStreamOptions options = {},
             std::shared_ptr<MaskPropagator> propagator = nullptr);
  ~MaskStream();
  MaskStream(const MaskStream&) = delete;
  MaskStream& operator=(const MaskStream&) = delete;

  // Masks for this frame (frames in increasing id order; bgr CV_8UC3; depth CV_32FC1 metres or
  // empty). With depth, the dynamic mask is snapped to the objects' depth outlines. Labels are
  // empty when the options do not carry them. The images are shared with the segmenter's thread,
  // not copied (two frames of copies per job were 4 MB, and a queued keyframe's 2 MB): the
  // caller must not write into them afterwards, i.e. give fresh images for every frame.
  SemanticMasks masksFor(std::uint64_t frame_id, const cv::Mat& bgr, const cv::Mat& depth,
                         const cv::Mat& known_dynamic = cv::Mat());

  // How much of its time the tracking thread spends computing rather than waiting for frames
  // (BusyShare); may be called from any thread. Unset, tracking counts as having CPU to spare.
  void setTrackingBusyShare(double share);

  // Asks for the segmenter's own output of a frame already handed on (a keyframe, whose map
  // points wait for it), ahead of every other frame, keyframes in order. The output comes
  // back once, through takeLateOutputs() with `keyframe` set: as soon as it is finished, or in
  // synchronous mode `latency_frames` frames after its frame. A frame whose output is already
  // there or on its way is not segmented twice. The images are shared, as for masksFor().
  void segmentKeyFrame(std::uint64_t frame_id, const cv::Mat& bgr, const cv::Mat& depth);

  // The outputs collected since the last call that belong to frames handed on before, oldest
  // first; each is taken once.
  [[nodiscard]] std::vector<LateOutput> takeLateOutputs();
  // After the last frame: takeLateOutputs() with every output still held back for its latency
  // (synchronous) or finished since the last frame, so that a keyframe made in the last frames
  // still gets its own mask.
  [[nodiscard]] std::vector<LateOutput> takeRemainingOutputs();

  // Segmenter runs finished so far and their mean time.
  [[nodiscard]] int runs() const;
  [[nodiscard]] double meanRunMilliseconds() const;

 private:
  struct Result {
    std::uint64_t frame_id;
    bool undecided;  // the segmenter could not tell: masks are all zero
    bool keyframe;   // a segmentKeyFrame() job
    SemanticMasks masks;
    std::vector<float> object_depths;  // of the dynamic objects, in the segmented frame
    cv::Mat depth;                     // of the segmented frame
  };

  // The newest output moved to the previous frame: each frame moves it one step further, so the
  // flow fields between the output's frame and now are applied once, not once per frame.
  struct Carried {
    std::uint64_t source_id;
    std::uint64_t frame_id;
    SemanticMasks masks;
  };

  // A lost object at the border, carried on its own (see border_linger_frames).
  struct Lingering {
    std::uint64_t seen_id;   // the frame of the last output that showed it
    std::uint64_t frame_id;  // the frame `dynamic` belongs to
    cv::Mat dynamic;
    std::vector<float> object_depths;
    int area;  // pixels when it was lost: at 1.5 times that it has joined a larger surface
  };

  void work();
  [[nodiscard]] SemanticMasks carryLatest(std::uint64_t frame_id, cv::Size size);
  // The lingering objects at this frame, given the frame's mask from the outputs (`fitted`).
  [[nodiscard]] cv::Mat lingeringObjects(const cv::Mat& fitted, const cv::Mat& depth,
                                         std::uint64_t frame_id);
  void addLostObjects(const cv::Mat& fitted, const cv::Mat& depth, std::uint64_t frame_id);
  void submit(SegmentationJob job);
  [[nodiscard]] bool segmenterWanted(std::uint64_t frame_id) const;
  void segmentSynchronously(const SegmentationJob& job);
  void collectFinished(std::uint64_t frame_id);
  void collect(Result result, std::uint64_t frame_id);
  [[nodiscard]] LateOutput lateOutput(const Result& result, bool keyframe) const;
  [[nodiscard]] Result run(const SegmentationJob& job);
  [[nodiscard]] cv::Mat fitToObjects(const cv::Mat& dynamic, const cv::Mat& depth,
                                     std::uint64_t frame_id) const;

  Segment segment_;
  MaskStreamOptions options_;
  std::shared_ptr<MaskPropagator> propagator_;
  StreamFrame previous_;          // the caller's last frame
  std::optional<Result> latest_;  // newest output, on the caller's side
  std::optional<Carried> carried_;
  std::optional<Lingering> lingering_;
  // The previous frame's mask from the outputs, and the output it came from.
  std::optional<Carried> last_fitted_;
  std::vector<LateOutput> late_;
  std::set<std::uint64_t> keyframes_asked_;  // frames whose output goes back as a keyframe's
  std::deque<Result> delayed_;  // synchronous outputs waiting for their latency, by frame
  std::optional<std::uint64_t> last_synchronous_run_;
  std::atomic<double> tracking_busy_share_{0.0};
  std::optional<std::uint64_t> last_submitted_;

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<SegmentationJob> pending_;  // frame waiting for the segmenter
  // Waiting too, before pending_, oldest first: local mapping takes keyframes in that order.
  std::deque<SegmentationJob> keyframe_jobs_;
  std::vector<Result> finished_;  // outputs not yet collected
  bool busy_ = false;
  bool stopping_ = false;
  int runs_ = 0;
  double total_ms_ = 0.0;
  std::thread thread_;
};

}  // namespace segslam::segmentation
