#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "segslam/map/frame.h"
#include "segslam/map/map.h"
#include "segslam/tracking/checked_pose.h"
#include "segslam/tracking/free_space_check.h"
#include "segslam/tracking/keyframe_database.h"
#include "segslam/tracking/keyframe_decision.h"
#include "segslam/tracking/keyframe_sink.h"
#include "segslam/tracking/late_mask_check.h"
#include "segslam/tracking/motion_limit.h"
#include "segslam/tracking/readout_estimator.h"

namespace segslam::tracking {

struct TrackerOptions {
  int min_initial_points = 500;  // keypoints with depth needed to start the map
  KeyFrameDecisionOptions keyframes;
  int min_new_points_per_keyframe = 100;
  // A keyframe makes map points from its keypoints with depth up to this many times the close
  // depth (map::FrameCamera::close_depth_m; beyond, only until it has
  // min_new_points_per_keyframe). ORB-SLAM2 stops at the close depth and adds farther points
  // later by triangulating between keyframes, which segslam does not do: without them a room
  // whose walls stand about 3 m away is mapped only on its nearer half, and the frames between
  // keyframes drift (synthetic 320x240 room lap, ATE 0.0142 -> 0.0105 m; the real
  // tum_fr1_xyz_300, a near scene, within 3 %). Twice the close depth (80 virtual baselines,
  // 6.1 m) keeps the depth a Kinect still measures usefully.
  double new_point_depth_factor = 2.0;
  int max_local_keyframes = 80;
  int min_inliers = 30;
  // Provisional map points (MapPoint::provisional) may refine a pose but not decide it.
  CheckedPoseOptions checked_pose;
  int min_inliers_after_relocalisation = 50;
  // Relocalisation needs this many of its inliers on points a keyframe's own mask has checked
  // (not MapPoint::provisional): a lost frame among people can match the points a person the
  // carried masks missed left in the map, and be placed by him.
  int min_checked_relocalisation_inliers = 20;
  // A pose farther from the last tracked frame's than a camera can move in the time between is
  // refused, tracked or relocalised: the frame is lost rather than made a keyframe of.
  MotionLimitOptions motion_limit;
  // A lost frame is matched against the keyframes that look most like it (by bag of words, given
  // a vocabulary: the camera may have been carried anywhere in the map), then against the most
  // recent ones (it may have lost track where it was, behind a person).
  std::size_t relocalisation_similar_keyframes = 10;
  std::size_t relocalisation_recent_keyframes = 15;
  // Map points that this many tracked frames' depth sees through are culled: they were on
  // something that has moved away (a person missed by a late mask). 0 = never.
  int seen_through_frames_to_cull = 2;
  FreeSpaceOptions free_space;
  // Late masks of frames up to this many frames old are applied to the map (0 = never).
  int late_mask_max_age = 60;
  DynamicSurfaceOptions late_mask;
  // Tracks against the map without changing it: no keyframes, no points, no culling (a loaded
  // map used for localisation only).
  bool localize_only = false;
};

enum class TrackingState { kNotInitialised, kOk, kLost };

struct TrackingResult {
  TrackingState state = TrackingState::kNotInitialised;
  int matches = 0;  // map points used for the pose (inliers)
  bool new_keyframe = false;
};

// Estimates each frame's pose against the map: constant-velocity prediction with projection
// search, falling back to descriptor matching against the reference keyframe, then to
// relocalisation; refines against the local map; decides when a keyframe is needed and
// creates map points from its depth. The caller holds map.mutex around track().
class Tracker {
 public:
  // Without a vocabulary, relocalisation tries the most recent keyframes only.
  Tracker(map::Map& map, KeyFrameSink& sink, TrackerOptions options = {},
          std::shared_ptr<const place::Vocabulary> vocabulary = nullptr);

  // without_mask, when given, makes the frame again with keypoints from the whole image: a frame
  // that the dynamic mask leaves too little static texture to track is tried once more with it
  // (a stale mask can cover the scene after its people left). Relocalisation is tried on that
  // one only.
  TrackingResult track(map::Frame frame, const std::function<map::Frame()>& without_mask = {});

  // The map was restored from a file before the first frame: tracking starts lost and
  // relocalises into it instead of starting a new map, wherever the camera is.
  void startInRestoredMap();

  // Culls the local map points that lie on what a late dynamic mask of an earlier frame marks
  // (tracking::pointsOnDynamicSurface). Frames older than the last few are ignored. Returns the
  // number of points culled.
  int cullPointsOnLateMask(std::uint64_t frame_id, const cv::Mat& dynamic_mask,
                           const cv::Mat& depth_m);

  [[nodiscard]] TrackingState state() const { return state_; }
  [[nodiscard]] const map::Frame& currentFrame() const { return current_; }
  // The map points the last local-map search looked for.
  [[nodiscard]] std::size_t localMapPoints() const { return local_points_.size(); }
  // The rolling-shutter readout estimated so far (ReadoutEstimator); empty before the first frame
  // or for a global-shutter camera.
  [[nodiscard]] std::optional<double> rollingShutterReadout() const;

  // A tracked frame's pose relative to its reference keyframe: resolving it against the
  // keyframe's final (optimised) pose gives the frame's final pose. Kept for every frame of the
  // session, so held as a quaternion and a translation: 72 bytes, not the 144 of a Pose.
  class FramePoseRecord {
   public:
    FramePoseRecord(double timestamp, map::KeyFrame* reference,
                    const geometry::Pose& T_c_reference);
    [[nodiscard]] geometry::Pose T_c_reference() const;

    double timestamp;
    map::KeyFrame* reference;

   private:
    Eigen::Quaternion<double, Eigen::DontAlign> rotation_;
    Eigen::Vector3d translation_;
  };
  // A deque: a session's records grow without the copy and the spare half of a vector's growth.
  [[nodiscard]] const std::deque<FramePoseRecord>& frameRecords() const { return records_; }

 private:
  bool initialise();
  enum class Placement { kNone, kTracked, kRelocalised };
  // Places current_ against the map: tracked from the last frame or the reference keyframe, or
  // relocalised when allowed; refined on the local map and within the camera's reach.
  Placement place(bool may_relocalise);
  bool trackWithMotionModel();
  bool trackReferenceKeyFrame();
  bool relocalise();
  // Whether a relocalisation candidate's pose places the current frame: refined, with enough
  // inliers, enough of them on points an own mask has checked.
  bool placedOn(const geometry::Pose& T_cw);
  [[nodiscard]] std::vector<std::shared_ptr<map::KeyFrame>> relocalisationCandidates() const;
  bool trackLocalMap();
  [[nodiscard]] bool movedPlausibly() const;
  [[nodiscard]] int checkedMatches() const;
  void addVisualOdometryPoints();
  int optimiseCurrentPose();
  void refineForRollingShutter();

  void updateLocalKeyFrames();
  void updateLocalPoints();
  int searchLocalMap();
  int trackedOfReference() const;
  bool needNewKeyFrame() const;
  void createKeyFrame();
  void addNewMapPoints(map::KeyFrame& keyframe);
  void dropTemporaryPoints();
  void cullPointsSeenThrough();
  void rememberPose();
  void recordPose();
  void reanchorLastFrame();
  // The rolling-shutter readout the frames are compensated with: estimated from the tracked
  // frames, starting from the camera's (ReadoutEstimator); 0 for a global-shutter camera.
  double readout();

  map::Map& map_;
  KeyFrameSink& sink_;
  TrackerOptions options_;
  std::optional<KeyFrameDatabase> keyframe_database_;
  TrackingState state_ = TrackingState::kNotInitialised;
  map::Frame current_;
  map::Frame last_;
  std::optional<geometry::Pose> velocity_;
  double velocity_dt_ = 0.0;  // seconds between the two frames velocity_ was measured on
  // The current frame's pose as velocity_ predicts it, while it is being tracked from the last.
  std::optional<geometry::Pose> predicted_T_cw_;
  std::shared_ptr<map::KeyFrame> reference_keyframe_;
  std::shared_ptr<map::KeyFrame> last_keyframe_;
  std::uint64_t last_keyframe_frame_id_ = 0;
  std::uint64_t last_relocalisation_frame_id_ = 0;
  std::vector<std::shared_ptr<map::KeyFrame>> local_keyframes_;
  std::vector<std::shared_ptr<map::MapPoint>> local_points_;
  // Tags the keyframes and points of one local-map search: a frame is searched again when its
  // first placement fails (relocalisation, the whole image), and tags by frame would then leave
  // it an empty local map.
  std::uint64_t local_map_searches_ = 0;
  std::vector<std::shared_ptr<map::MapPoint>> temporary_points_;
  int inliers_ = 0;
  ReferenceOverlap reference_overlap_;
  std::deque<FramePoseRecord> records_;
  // Poses of the last tracked frames, for late masks.
  std::deque<std::pair<std::uint64_t, geometry::Pose>> recent_poses_;
  std::uint64_t seen_corrections_ = 0;
  std::optional<ReadoutEstimator> readout_estimator_;
};

}  // namespace segslam::tracking
