#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "segslam/map/map.h"
#include "segslam/tracking/keyframe_sink.h"

namespace segslam::mapping {

struct LocalMapperOptions {
  int fusion_neighbours = 10;     // covisible keyframes searched for duplicate points
  int ba_first_iterations = 5;    // with robust kernel
  int ba_second_iterations = 10;  // after removing outliers
  // The new keyframe and its best covisible neighbours are optimised; capping their number
  // keeps a local BA near 100 ms when the whole map is covisible (a camera dwelling on a desk).
  int ba_max_keyframes = 20;
  double redundant_keyframe_share = 0.9;
  bool cull_keyframes = true;
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
  [[nodiscard]] bool isIdle() const override;
  [[nodiscard]] std::size_t queuedKeyFrames() const override;

  void start();
  // Processes what is queued, then stops the thread.
  void finish();
  // Processes every queued keyframe on the calling thread.
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
  std::shared_ptr<map::KeyFrame> popKeyFrame();
  void processKeyFrame(const std::shared_ptr<map::KeyFrame>& keyframe);
  void integrateKeyFrame(map::KeyFrame& keyframe);
  void cullRecentPoints(const map::KeyFrame& keyframe);
  void fuseWithNeighbours(map::KeyFrame& keyframe);
  void localBundleAdjustment(map::KeyFrame& keyframe);
  void cullRedundantKeyFrames(map::KeyFrame& keyframe);

  map::Map& map_;
  LocalMapperOptions options_;
  std::vector<std::shared_ptr<map::MapPoint>> recent_points_;

  mutable std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  std::deque<std::shared_ptr<map::KeyFrame>> queue_;
  bool busy_ = false;
  bool stopping_ = false;
  bool paused_ = false;
  std::function<void(std::shared_ptr<map::KeyFrame>)> observer_;
  std::thread thread_;
  double ba_seconds_ = 0.0;
};

}  // namespace segslam::mapping
