#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "segslam/core/camera.h"
#include "segslam/core/trajectory.h"
#include "segslam/dense/dense_map.h"
#include "segslam/dense/keyframe_cloud.h"
#include "segslam/dense/object_map_builder.h"
#include "segslam/dense/packed_cloud.h"

namespace segslam::dense {

struct MapBuilderOptions {
  KeyFrameCloudOptions keyframe;  // its voxel_size is the map's
  CloudCleaningOptions cleaning;
  ObjectMapOptions objects;  // its cell size is at least 2 voxels
  // Niceness of the map thread: tracking comes first, a keyframe cloud can wait.
  int thread_niceness = 10;
  // No map thread: clouds are made and culled ones folded on the caller's thread as they are
  // handed over. Which clouds a fold finds, and under which poses, then no longer depends on
  // when the map thread ran, so a deterministic run gives the same map every time.
  bool synchronous = false;
};

// What one keyframe of the built map saw, in the world: handed to a KeyFrameScanSink by
// MapBuilder::build (an occupancy map casts its rays from `origin`). The static points include
// what the culled keyframes folded into it saw.
using KeyFrameScanSink =
    std::function<void(const Eigen::Vector3d& origin, const LabelledCloud& static_points,
                       const LabelledCloud& dynamic_points)>;

// Where map building spends its time, seconds: CPU time of the map thread for the keyframe
// clouds (it runs beside tracking), wall time of the last build() (after tracking).
struct MapTimings {
  double back_projection = 0.0;
  double keyframe_voxels = 0.0;
  double merging = 0.0;  // keyframe clouds into the world frame, voxelised together
  double outlier_removal = 0.0;
  double objects = 0.0;
  double scans = 0.0;  // handing the keyframes' points to a KeyFrameScanSink (occupancy)
};

// Builds the dense map of a run off the tracking thread. Keyframes are handed over as they are
// made; a worker thread (the caller's, when synchronous) turns each into a voxelised cloud in its
// own camera frame, kept packed (PackedKeyFrameCloud: a long session holds one per live
// keyframe). The world map is assembled only in build(), from whatever keyframe poses are final
// then, so a loop correction needs nothing but another build() with the corrected poses.
class MapBuilder {
 public:
  MapBuilder(const core::Camera& camera, MapBuilderOptions options);
  ~MapBuilder();
  MapBuilder(const MapBuilder&) = delete;
  MapBuilder& operator=(const MapBuilder&) = delete;

  // Queues a keyframe and returns at once (synchronous: once its cloud is made). The images are
  // shared, not copied: the caller must not write into them afterwards. Timestamps must be unique.
  void addKeyFrame(std::uint64_t id, double timestamp, KeyFrameImages images);
  // The latest poses of the live keyframes (camera to world, e.g. SLAM's keyframe trajectory
  // after each new keyframe). A keyframe whose cloud the map holds, older than the newest of them
  // and missing from them, was culled: its cloud is folded into the cloud of the live keyframe
  // with the nearest view (foldInto), so what it saw stays in the map while the clouds kept are
  // as many as the live keyframes, not as all keyframes ever made. Returns at once and the map
  // thread folds (synchronous: returns folded). A keyframe culled before any of these calls saw it
  // live is left out (dropped).
  void setLiveKeyFrames(core::Trajectory live);
  // The static map of an earlier session, in this run's world frame (a loaded map file's dense
  // map): build() keeps its points that none of this run's keyframes sees through
  // (withoutSeenThrough), so what moved away since goes and what this run did not look at stays.
  void setEarlierMap(LabelledCloud static_points);
  // Waits until every queued keyframe has its cloud and the last setLiveKeyFrames is folded;
  // rethrows the first error a keyframe gave (images of the wrong type or size).
  void finish();

  // The world map: every keyframe cloud whose timestamp has a pose in `keyframe_poses`
  // (camera-to-world, matched within 1e-4 s) transformed into the world, merged, voxelised once
  // more and cleaned of outliers; keyframes without a pose (culled ones) are folded into the
  // nearest live one first where their last pose is known, else left out. Objects
  // come from the keyframes' labels (ObjectMapBuilder). Each keyframe's points in the world go to
  // `scans` too, when given. Waits for the queue first.
  [[nodiscard]] DenseMap build(const core::Trajectory& keyframe_poses,
                               const KeyFrameScanSink& scans = {});

  [[nodiscard]] std::size_t numKeyFrames();
  [[nodiscard]] MapTimings timings();

 private:
  struct QueuedKeyFrame {
    std::uint64_t id = 0;
    double timestamp = 0.0;
    KeyFrameImages images;
  };
  struct StoredCloud {
    std::uint64_t id = 0;
    PackedKeyFrameCloud cloud;
    std::optional<Eigen::Isometry3d> T_wc;  // its latest pose from setLiveKeyFrames
  };
  using Clouds = std::map<double, StoredCloud>;  // by timestamp

  void work();
  // A live set is folded only once no cloud is being made: a keyframe whose cloud lands after the
  // fold would miss being culled by it.
  [[nodiscard]] bool foldDue() const;
  // Folds the latest live set (pending_live_), unlocking `lock` meanwhile.
  void foldPending(std::unique_lock<std::mutex>& lock);
  // Folds the clouds of keyframes missing from `live` (older than its newest keyframe when
  // `only_older`) into the live ones; the folding itself runs with `lock` released.
  void foldCulled(const core::Trajectory& live, bool only_older,
                  std::unique_lock<std::mutex>& lock);
  // Makes the cloud of the queue's first keyframe, unlocking `lock` meanwhile.
  void makeFront(std::unique_lock<std::mutex>& lock);
  struct WorldClouds {
    LabelledCloud static_points;
    LabelledCloud dynamic_points;
    double object_seconds = 0.0;  // spent associating the keyframes' objects
    double scan_seconds = 0.0;    // spent in the KeyFrameScanSink
    std::size_t earlier_points_removed = 0;
  };
  // Both layers of every keyframe with a pose, in the world frame, voxelised together; each
  // keyframe's are handed to `objects` on the way.
  [[nodiscard]] WorldClouds worldClouds(const core::Trajectory& keyframe_poses,
                                        ObjectMapBuilder& objects,
                                        const KeyFrameScanSink& scans) const;

  core::Camera camera_;
  KeyFrameCloudMaker maker_;
  MapBuilderOptions options_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<QueuedKeyFrame> queue_;
  int working_ = 0;  // threads making a cloud or folding with the lock released
  bool stopping_ = false;
  Clouds clouds_;
  std::optional<core::Trajectory> pending_live_;
  std::optional<LabelledCloud> earlier_;  // setEarlierMap  // for the map thread to fold
  // Poses of live keyframes whose clouds are not made yet (by the keyframe's exact timestamp).
  std::map<double, geometry::Pose> poses_before_cloud_;
  MapTimings timings_;
  std::exception_ptr error_;
  std::thread worker_;  // none when synchronous
};

}  // namespace segslam::dense
