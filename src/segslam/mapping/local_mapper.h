#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "segslam/map/map.h"
#include "segslam/mapping/keyframe_culling.h"
#include "segslam/mapping/keyframe_mask.h"
#include "segslam/tracking/keyframe_sink.h"

namespace segslam::mapping {

struct LocalMapperOptions {
  int fusion_neighbours = 10;     // covisible keyframes searched for duplicate points
  int ba_first_iterations = 5;    // with robust kernel
  int ba_second_iterations = 10;  // after removing outliers
  // The new keyframe and its best covisible neighbours are optimised; capping their number
  // keeps a local BA near 100 ms when the whole map is covisible (a camera dwelling on a desk).
  int ba_max_keyframes = 20;
  KeyFrameCullingOptions culling;
  bool cull_keyframes = true;
  // A keyframe waits in the queue for its own dynamic mask (addKeyFrameMask: a segmentation
  // network's output for its frame, which arrives after tracking made the keyframe) for at most
  // this many tracked frames, so that bundle adjustment, fusion and loop closing never see the
  // points it made on a moving object. 0 = keyframes never wait.
  int own_mask_wait_frames = 0;
  OwnMaskOptions own_mask;
};

// What the keyframes' own masks did (LocalMapperOptions::own_mask_wait_frames).
struct OwnMaskStats {
  int keyframes_with_own_mask = 0;
  int keyframes_without = 0;  // waited the longest, or their mask came too late
  int points_culled = 0;
  int observations_dropped = 0;
  double mean_wait_frames = 0.0;  // of the keyframes whose mask came
};

// Local mapping: integrates each new keyframe into the covisibility graph, culls weak recent
// points, fuses duplicates with neighbouring keyframes, runs local bundle adjustment and removes
// redundant keyframes. Runs on its own thread (start()) or synchronously (processQueued()) for
// reproducible runs. It holds the map mutex only while reading or writing the map, never while
// optimising.
class LocalMapper : public tracking::KeyFrameSink {
 public:
  LocalMapper(map::Map& map, LocalMapperOptions options = {});
  ~LocalMapper() override;
  LocalMapper(const LocalMapper&) = delete;
  LocalMapper& operator=(const LocalMapper&) = delete;

  void insertKeyFrame(std::shared_ptr<map::KeyFrame> keyframe) override;
  // Idle: no keyframe queued, not even one waiting for its own mask: tracking makes keyframes
  // more readily while mapping is idle, and keyframes made while a person is not yet masked
  // would each wait with points on him.
  [[nodiscard]] bool isIdle() const override;
  [[nodiscard]] std::size_t queuedKeyFrames() const override;

  // The own dynamic mask of the keyframe made from frame `frame_id` (CV_8UC1, non-zero = dynamic,
  // dilated as the frames' masks are), from any thread. A mask that comes after its keyframe
  // stopped waiting is dropped.
  void addKeyFrameMask(std::uint64_t frame_id, cv::Mat dilated_mask);
  // The last frame tracking has handled, from any thread: keyframes that have waited
  // own_mask_wait_frames frames for their mask are mapped without it.
  void setTrackedFrame(std::uint64_t frame_id);
  [[nodiscard]] OwnMaskStats ownMaskStats() const;

  void start();
  // Processes what is queued, then stops the thread; keyframes stop waiting for their masks.
  void finish();
  // Processes the queued keyframes on the calling thread, up to the first that still waits for
  // its own mask.
  void processQueued();

  // Called (without the map mutex) with each keyframe that survived its processing: the loop
  // closer's queue. Set before start().
  void setProcessedKeyFrameObserver(std::function<void(std::shared_ptr<map::KeyFrame>)> observer) {
    observer_ = std::move(observer);
  }
  // Loop correction rewrites the map: pause() returns once the keyframe in progress is done and
  // keeps the thread waiting (keyframes still queue up) until resume().
  void pause();
  void resume();

  [[nodiscard]] double totalBundleAdjustmentSeconds() const { return ba_seconds_; }

 private:
  void run();
  // Whether the queue's first keyframe may be mapped now (queue_mutex_ held).
  [[nodiscard]] bool frontReady() const;
  // The same, taking the lock: a keyframe ready behind the one in hand skips its local BA.
  [[nodiscard]] bool keyFrameReady() const;
  // The queue's first keyframe with its own mask (empty when it has none), if it is ready.
  struct ReadyKeyFrame {
    std::shared_ptr<map::KeyFrame> keyframe;
    cv::Mat own_mask;
  };
  [[nodiscard]] ReadyKeyFrame takeFront();  // queue_mutex_ held
  std::optional<ReadyKeyFrame> popKeyFrame();
  void applyOwnMaskOf(const ReadyKeyFrame& ready);
  void processKeyFrame(const std::shared_ptr<map::KeyFrame>& keyframe);
  void integrateKeyFrame(map::KeyFrame& keyframe);
  void cullRecentPoints(const map::KeyFrame& keyframe);
  void fuseWithNeighbours(map::KeyFrame& keyframe);
  void localBundleAdjustment(map::KeyFrame& keyframe);
  void cullRedundantKeyFrames(map::KeyFrame& keyframe);
  // Orphaned keyframes have no covisibility edge that would bring them before the rule above.
  void cullOrphanedKeyFrames(const map::KeyFrame& keyframe);

  map::Map& map_;
  LocalMapperOptions options_;
  std::vector<std::shared_ptr<map::MapPoint>> recent_points_;

  mutable std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  std::deque<std::shared_ptr<map::KeyFrame>> queue_;
  std::map<std::uint64_t, cv::Mat> own_masks_;  // by frame id, until their keyframe is mapped
  std::uint64_t tracked_frame_ = 0;
  OwnMaskStats own_mask_stats_;
  double own_mask_wait_total_ = 0.0;
  bool busy_ = false;
  bool stopping_ = false;
  bool paused_ = false;
  std::function<void(std::shared_ptr<map::KeyFrame>)> observer_;
  std::thread thread_;
  double ba_seconds_ = 0.0;
};

}  // namespace segslam::mapping
