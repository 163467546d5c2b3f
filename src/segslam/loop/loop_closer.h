#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "segslam/geometry/pose.h"
#include "segslam/loop/consistency_check.h"
#include "segslam/loop/loop_candidate_detector.h"
#include "segslam/loop/loop_verifier.h"
#include "segslam/loop/pose_graph.h"
#include "segslam/map/map.h"
#include "segslam/mapping/local_mapper.h"

namespace segslam::loop {

struct LoopClosingOptions {
  std::uint64_t min_keyframes = 5;  // keyframes made (culled ones too) before loops are sought
  std::uint64_t keyframes_after_loop = 10;  // keyframes skipped after a correction
  std::size_t max_candidates = 3;           // per query keyframe, from the detector
  // A candidate made fewer keyframes before the query is the same stretch of path, not a loop,
  // even when they share no point (a person hid their common view, or tracking was recovered
  // between them): "closing" it bends the map without reducing drift.
  std::uint64_t min_keyframes_back = 10;
  // Consecutive query keyframes that must propose the same place (see ConsistencyCheck). 1: a
  // revisited place is often verified by a single keyframe (the end of a lap overlaps its start
  // for a few keyframes only); the strict geometric verification is what keeps false loops out.
  int consecutive_queries = 1;
  std::size_t loop_local_keyframes = 10;  // the candidate's covisibles whose points verify it
  LoopVerifierOptions verifier;
  int essential_covisibility_weight = 100;  // covisibility edges kept in the pose graph
  PoseGraphOptions pose_graph;
  bool global_bundle_adjustment = true;
  int global_ba_first_iterations = 5;
  int global_ba_second_iterations = 5;
};

// One accepted loop: the query keyframe was found to see the loop keyframe's place.
struct LoopRecord {
  std::uint64_t query_keyframe = 0;
  std::uint64_t loop_keyframe = 0;
  double query_timestamp = 0.0;
  double loop_timestamp = 0.0;
  // The verified relative pose T_query_loop (maps loop-camera coordinates into the query's).
  geometry::Pose T_query_loop = geometry::Pose::Identity();
  int inliers = 0;
  double drift_m = 0.0;  // how far the correction moved the query keyframe
};

struct LoopClosingStats {
  std::string detector;           // LoopCandidateDetector::name()
  int consistent_candidates = 0;  // candidates that reached geometric verification
  int loops_accepted = 0;
  int global_bas_completed = 0;
  int global_bas_cancelled = 0;
  // LoopCandidateDetector::describe() per keyframe (the CNN's forward pass), wall time on the
  // loop-closing thread.
  int keyframes_described = 0;
  double describe_ms_total = 0.0;
  std::vector<LoopRecord> loops;
};

// The loop-closing thread: takes each keyframe local mapping is done with, asks the detector
// for candidates, keeps those confirmed by consecutive queries, verifies them geometrically and,
// on an accepted loop, pauses local mapping, corrects the query's neighbourhood with the loop
// transform, fuses the duplicated points, optimises the essential graph (spanning tree, strong
// covisibility, loop edges) and starts a global bundle adjustment in the background (cancelled
// by the next loop). Tracking goes on throughout: the map mutex is held only to read or write
// the map, never while verifying or optimising. In deterministic mode (no start()) everything,
// global BA included, runs in processQueued() on the caller's thread.
class LoopCloser {
 public:
  LoopCloser(map::Map& map, mapping::LocalMapper& mapper,
             std::unique_ptr<LoopCandidateDetector> detector, LoopClosingOptions options = {});
  ~LoopCloser();
  LoopCloser(const LoopCloser&) = delete;
  LoopCloser& operator=(const LoopCloser&) = delete;

  void insertKeyFrame(std::shared_ptr<map::KeyFrame> keyframe);
  // A keyframe of a map restored from a file, before the first frame, with the description the
  // detector saved of it (savedDescription): a loop candidate for the keyframes to come, never a
  // query itself. The caller holds the map mutex.
  void addRestoredKeyFrame(map::KeyFrame& keyframe, const std::string& description);
  // What a map file keeps of a keyframe for the detector (LoopCandidateDetector::
  // savedDescription). After finish(); the caller holds the map mutex.
  [[nodiscard]] std::string savedDescription(std::uint64_t keyframe_id) const;
  void start();
  // Processes what is queued, waits for the global BA, then stops the thread.
  void finish();
  void processQueued();

  [[nodiscard]] LoopClosingStats stats() const;

 private:
  struct Snapshot;

  void run();
  std::shared_ptr<map::KeyFrame> popKeyFrame();
  void processKeyFrame(const std::shared_ptr<map::KeyFrame>& keyframe);
  // The detector forgets the keyframes culled since the last call, and the map frees their
  // features up to the keyframe just described. Map mutex held.
  void forgetCulledKeyFrames(std::uint64_t described);
  std::vector<std::uint64_t> confirmedCandidates(map::KeyFrame& keyframe);
  bool tryLoop(const std::shared_ptr<map::KeyFrame>& query, std::uint64_t candidate_id);
  void correctLoop(map::KeyFrame& query, map::KeyFrame& loop_keyframe,
                   const LoopVerification& verification,
                   const std::vector<std::shared_ptr<map::MapPoint>>& loop_points);
  void optimiseEssentialGraph(
      const std::map<const map::KeyFrame*, geometry::Pose>& before,
      const std::vector<std::pair<map::KeyFrame*, map::KeyFrame*>>& new_loop_edges);
  void startGlobalBundleAdjustment();
  void globalBundleAdjustment();
  void stopGlobalBundleAdjustment();

  map::Map& map_;
  mapping::LocalMapper& mapper_;
  std::unique_ptr<LoopCandidateDetector> detector_;
  LoopClosingOptions options_;
  ConsistencyCheck consistency_;
  std::map<std::uint64_t, map::KeyFrame*> keyframes_by_id_;
  std::vector<std::pair<map::KeyFrame*, map::KeyFrame*>> loop_edges_;
  std::uint64_t last_loop_keyframe_ = 0;
  bool any_loop_ = false;

  mutable std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  std::deque<std::shared_ptr<map::KeyFrame>> queue_;
  bool stopping_ = false;
  std::thread thread_;

  mutable std::mutex stats_mutex_;
  LoopClosingStats stats_;

  std::thread global_ba_thread_;
  std::atomic<bool> cancel_global_ba_{false};
};

}  // namespace segslam::loop
