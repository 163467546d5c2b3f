#include "segslam/tracking/tracker.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "segslam/optim/pose_optimizer.h"
#include "segslam/tracking/projection_search.h"
#include "segslam/tracking/relocaliser.h"

namespace segslam::tracking {

namespace {

constexpr int kMinPoseMatches = 10;
constexpr double kMotionSearchRadius = 15.0;  // pixels at level 0, as ORB-SLAM2 for RGB-D
constexpr double kLocalMapRadius = 3.0;
constexpr double kLocalMapRadiusAfterRelocalisation = 5.0;

// Indices of keypoints with depth, nearest first.
std::vector<std::size_t> keypointsByDepth(const map::Frame& frame) {
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    if (frame.depth[i] > 0.0f) indices.push_back(i);
  }
  std::stable_sort(indices.begin(), indices.end(),
                   [&](std::size_t a, std::size_t b) { return frame.depth[a] < frame.depth[b]; });
  return indices;
}

bool hasMapPoint(const map::Frame& frame, std::size_t i) {
  const auto& p = frame.map_points[i];
  return p && !p->bad && p->numObservations() > 0;
}

}  // namespace

Tracker::Tracker(map::Map& map, KeyFrameSink& sink, TrackerOptions options,
                 std::shared_ptr<const place::Vocabulary> vocabulary)
    : map_(map), sink_(sink), options_(options) {
  if (vocabulary) keyframe_database_.emplace(std::move(vocabulary));
}

TrackingResult Tracker::track(map::Frame frame, const std::function<map::Frame()>& without_mask) {
  last_ = std::move(current_);
  current_ = std::move(frame);
  if (map_.corrections() != seen_corrections_) {
    seen_corrections_ = map_.corrections();
    reanchorLastFrame();
  }
  TrackingResult result;
  if (state_ == TrackingState::kNotInitialised) {
    if (initialise()) state_ = TrackingState::kOk;
    result.state = state_;
    result.new_keyframe = state_ == TrackingState::kOk;
    if (state_ == TrackingState::kOk) recordPose();
    return result;
  }

  Placement placement = place(!without_mask);
  if (placement == Placement::kNone && without_mask) {
    current_ = without_mask();
    placement = place(true);
  }
  const bool ok = placement != Placement::kNone;
  const bool relocalised = placement == Placement::kRelocalised;

  if (ok) {
    state_ = TrackingState::kOk;
    // After relocalisation the last frame's pose says nothing about the camera's motion.
    if (relocalised) {
      spdlog::info("frame {}: relocalised against keyframe {}", current_.id,
                   reference_keyframe_->id);
      velocity_.reset();
    } else {
      velocity_ = geometry::orthonormalised(current_.T_cw * last_.T_cw.inverse());
      velocity_dt_ = current_.timestamp - last_.timestamp;
    }
    if (!options_.localize_only) cullPointsSeenThrough();
    rememberPose();
    reference_overlap_.update(reference_keyframe_->id, trackedOfReference());
    if (!options_.localize_only && needNewKeyFrame()) {
      createKeyFrame();
      result.new_keyframe = true;
    }
    dropTemporaryPoints();
    recordPose();
  } else {
    state_ = TrackingState::kLost;
    velocity_.reset();
    current_.has_pose = false;
    spdlog::debug("frame {}: tracking lost", current_.id);
  }
  result.state = state_;
  result.matches = inliers_;
  return result;
}

Tracker::Placement Tracker::place(bool may_relocalise) {
  // Rows read while the camera moved as it did over the last frames: a first placement of the
  // keypoints for the search, refined once the frame's own motion is known.
  if (velocity_ && readout() != 0.0) {
    current_.compensateRollingShutter(*velocity_, velocity_dt_, readout());
  }
  predicted_T_cw_.reset();
  const bool tracked = state_ == TrackingState::kOk &&
                       ((velocity_ && trackWithMotionModel()) || trackReferenceKeyFrame());
  if (tracked && trackLocalMap() && movedPlausibly()) {
    refineForRollingShutter();
    return Placement::kTracked;
  }
  // A frame that loses track tries relocalisation at once: the camera may have been carried
  // elsewhere, and the frame is as good a query as the next. A relocalised pose must be within
  // reach of the last tracked one as much as a tracked pose: a lost frame's descriptors can
  // match a person or a look-alike place anywhere in the map.
  predicted_T_cw_.reset();
  if (!may_relocalise || !relocalise() || !trackLocalMap() || !movedPlausibly()) {
    return Placement::kNone;
  }
  return Placement::kRelocalised;
}

bool Tracker::movedPlausibly() const {
  // The last tracked frame, placed by its reference keyframe as the map is now (a loop correction
  // may have moved it since); none before the first or in a restored map not yet localised in.
  if (records_.empty() || records_.back().reference->bad) return true;
  const FramePoseRecord& last = records_.back();
  const geometry::Pose last_T_cw = last.T_c_reference() * last.reference->T_cw;
  if (withinMotionLimit(last_T_cw, last.timestamp, current_.T_cw, current_.timestamp,
                        options_.motion_limit)) {
    return true;
  }
  spdlog::debug("frame {}: pose {:.2f} m from the last tracked frame's in {:.3f} s, refused",
                current_.id,
                (current_.T_cw.inverse().translation() - last_T_cw.inverse().translation()).norm(),
                current_.timestamp - last.timestamp);
  return false;
}

void Tracker::startInRestoredMap() {
  state_ = TrackingState::kLost;
  if (!keyframe_database_) return;
  for (const auto& keyframe : map_.keyFrames()) keyframe_database_->add(keyframe);
}

bool Tracker::initialise() {
  if (static_cast<int>(keypointsByDepth(current_).size()) < options_.min_initial_points) {
    spdlog::debug("frame {}: too few keypoints with depth to start the map", current_.id);
    return false;
  }
  current_.T_cw = geometry::Pose::Identity();
  current_.has_pose = true;
  auto keyframe = map_.createKeyFrame(current_);
  for (std::size_t i : keypointsByDepth(current_)) {
    auto point = map_.createMapPoint(keyframe->unproject(i), keyframe.get());
    point->provisional = true;
    point->addObservation(keyframe.get(), i);
    keyframe->addMapPoint(point, i);
    point->updateDescriptor();
    point->updateNormalAndDepth();
    current_.map_points[i] = point;
  }
  spdlog::info("map initialised with {} points", map_.numMapPoints());
  reference_keyframe_ = keyframe;
  last_keyframe_ = keyframe;
  last_keyframe_frame_id_ = current_.id;
  current_.reference_keyframe = keyframe;
  local_keyframes_ = {keyframe};
  local_points_ = map_.mapPoints();
  if (keyframe_database_) keyframe_database_->add(keyframe);
  sink_.insertKeyFrame(keyframe);
  return true;
}

void Tracker::addVisualOdometryPoints() {
  // RGB-D gives every keypoint of the last frame a 3D position: temporary points (not in the
  // map) for its unmatched close keypoints make the motion-model search far more robust when
  // the map is thin, as ORB-SLAM2 does.
  const double close_depth = last_.camera->close_depth_m;
  int added = 0;
  for (std::size_t i : keypointsByDepth(last_)) {
    if (hasMapPoint(last_, i)) continue;
    if (last_.depth[i] > close_depth && added > options_.min_new_points_per_keyframe) break;
    const Eigen::Vector3d position = last_.T_cw.inverse() * last_.unproject(i);
    auto point = std::make_shared<map::MapPoint>(UINT64_MAX, position, nullptr);
    point->provisional = true;
    point->descriptor = last_.descriptors.row(static_cast<int>(i)).clone();
    last_.map_points[i] = point;
    last_.outlier[i] = false;
    temporary_points_.push_back(point);
    ++added;
  }
}

bool Tracker::trackWithMotionModel() {
  addVisualOdometryPoints();
  current_.T_cw = geometry::orthonormalised(*velocity_ * last_.T_cw);
  predicted_T_cw_ = current_.T_cw;
  std::fill(current_.map_points.begin(), current_.map_points.end(), nullptr);
  int matches = searchFromLastFrame(current_, last_, kMotionSearchRadius);
  if (matches < 20) {
    std::fill(current_.map_points.begin(), current_.map_points.end(), nullptr);
    matches = searchFromLastFrame(current_, last_, 2.0 * kMotionSearchRadius);
  }
  if (matches < 20) return false;
  const int inliers = optimiseCurrentPose();
  spdlog::debug("frame {}: motion model: {} matches, {} inliers", current_.id, matches, inliers);
  return inliers >= kMinPoseMatches;
}

bool Tracker::trackReferenceKeyFrame() {
  std::fill(current_.map_points.begin(), current_.map_points.end(), nullptr);
  // A reference culled since the last frame may have had its features freed: its nearest live
  // ancestor in the pose tree sees about the same.
  while (reference_keyframe_->bad && reference_keyframe_->parent) {
    reference_keyframe_ = reference_keyframe_->parent->shared_from_this();
  }
  if (searchByDescriptors(current_, *reference_keyframe_, 0.7) < 15) return false;
  current_.T_cw = last_.has_pose ? last_.T_cw : reference_keyframe_->T_cw;
  return optimiseCurrentPose() >= kMinPoseMatches;
}

bool Tracker::relocalise() {
  std::fill(current_.map_points.begin(), current_.map_points.end(), nullptr);
  const auto placed =
      relocaliseAgainstKeyFrames(current_, relocalisationCandidates(),
                                 [this](const geometry::Pose& T_cw) { return placedOn(T_cw); });
  if (!placed) return false;
  last_relocalisation_frame_id_ = current_.id;
  reference_keyframe_ = current_.reference_keyframe;
  spdlog::debug("frame {}: placed against keyframe {}", current_.id,
                current_.reference_keyframe->id);
  return true;
}

bool Tracker::placedOn(const geometry::Pose& T_cw) {
  current_.T_cw = T_cw;
  // The candidate keyframe's own points need only place the frame: the local map around it,
  // searched next (trackLocalMap), must then bring the inliers up to
  // min_inliers_after_relocalisation. One keyframe seldom shows that many through a person or
  // motion blur, and the camera stayed lost where the local map would have found it.
  if (optimiseCurrentPose() < options_.min_inliers) return false;
  const int checked = checkedMatches();
  if (checked < options_.min_checked_relocalisation_inliers) {
    spdlog::debug(
        "frame {}: relocalisation against keyframe {} refused: only {} of its inliers on "
        "points an own mask has checked",
        current_.id, current_.reference_keyframe->id, checked);
    return false;
  }
  return true;
}

int Tracker::checkedMatches() const {
  int checked = 0;
  for (const auto& point : current_.map_points) {
    if (point && !point->bad && !point->provisional) ++checked;
  }
  return checked;
}

std::vector<std::shared_ptr<map::KeyFrame>> Tracker::relocalisationCandidates() const {
  std::vector<std::shared_ptr<map::KeyFrame>> candidates;
  if (keyframe_database_) {
    candidates =
        keyframe_database_->candidates(current_, options_.relocalisation_similar_keyframes);
  }
  const auto keyframes = map_.keyFrames();
  std::size_t recent = 0;
  for (auto it = keyframes.rbegin();
       it != keyframes.rend() && recent < options_.relocalisation_recent_keyframes; ++it) {
    if (std::find(candidates.begin(), candidates.end(), *it) != candidates.end()) continue;
    candidates.push_back(*it);
    ++recent;
  }
  return candidates;
}

int Tracker::optimiseCurrentPose() {
  std::vector<optim::PoseObservation> observations;
  std::vector<bool> provisional;
  std::vector<std::size_t> keypoint_of;
  for (std::size_t i = 0; i < current_.size(); ++i) {
    const auto& point = current_.map_points[i];
    if (!point || point->bad) continue;
    observations.push_back({point->position, current_.observation(i)});
    provisional.push_back(point->provisional);
    keypoint_of.push_back(i);
  }
  if (observations.size() < static_cast<std::size_t>(kMinPoseMatches)) return 0;
  const auto result =
      optimizePoseTrustingCheckedMatches(current_.camera->stereo, current_.T_cw, observations,
                                         provisional, predicted_T_cw_, options_.checked_pose);
  current_.T_cw = result.T_cw;
  current_.has_pose = true;
  for (std::size_t k = 0; k < keypoint_of.size(); ++k) {
    const std::size_t i = keypoint_of[k];
    if (!result.inlier[k]) current_.map_points[i].reset();
    current_.outlier[i] = false;
  }
  return result.num_inliers;
}

void Tracker::refineForRollingShutter() {
  // The frame's own motion from the last frame places its rows far better than the last
  // frames' (a hand-held camera's motion changes within a frame period): ATE on
  // tum_fr1_xyz_300 0.0074 -> 0.0049 m (bench/results/rolling_shutter.md). The full, robust
  // optimisation again: one plain round lost frames on fast walkers the masks missed.
  const double readout_s = readout();
  if (readout_s == 0.0) return;
  current_.compensateRollingShutter(geometry::orthonormalised(current_.T_cw * last_.T_cw.inverse()),
                                    current_.timestamp - last_.timestamp, readout_s);
  optimiseCurrentPose();
  readout_estimator_->addFrame(readoutEvidence(current_, readout_s));
}

std::optional<double> Tracker::rollingShutterReadout() const {
  if (!readout_estimator_ || readout_estimator_->readout() == 0.0) return std::nullopt;
  return readout_estimator_->readout();
}

double Tracker::readout() {
  if (!readout_estimator_) {
    const core::Camera& camera = current_.camera->camera;
    readout_estimator_.emplace(camera.rolling_shutter_readout_s, 1.0 / camera.fps);
  }
  return readout_estimator_->readout();
}

bool Tracker::trackLocalMap() {
  ++local_map_searches_;
  updateLocalKeyFrames();
  updateLocalPoints();
  searchLocalMap();
  optimiseCurrentPose();
  inliers_ = 0;
  for (std::size_t i = 0; i < current_.size(); ++i) {
    const auto& point = current_.map_points[i];
    if (!point || point->bad) continue;
    point->increaseFound();
    if (point->numObservations() > 0) ++inliers_;
  }
  const bool recently_relocalised =
      last_relocalisation_frame_id_ > 0 &&
      current_.id < last_relocalisation_frame_id_ + options_.keyframes.max_frames_between_keyframes;
  const int needed =
      recently_relocalised ? options_.min_inliers_after_relocalisation : options_.min_inliers;
  if (inliers_ < needed) {
    spdlog::debug("frame {}: local map: {} inliers, {} needed", current_.id, inliers_, needed);
  }
  return inliers_ >= needed;
}

void Tracker::updateLocalKeyFrames() {
  std::map<map::KeyFrame*, int, map::KeyFrameIdLess> votes;
  for (const auto& point : current_.map_points) {
    if (!point || point->bad) continue;
    for (const auto& [keyframe, index] : point->observations()) ++votes[keyframe];
  }
  if (votes.empty()) return;
  local_keyframes_.clear();
  auto add = [&](map::KeyFrame* keyframe) {
    if (keyframe == nullptr || keyframe->bad || keyframe->local_map_search == local_map_searches_) {
      return;
    }
    keyframe->local_map_search = local_map_searches_;
    local_keyframes_.push_back(keyframe->shared_from_this());
  };
  map::KeyFrame* best = nullptr;
  int best_votes = 0;
  for (const auto& [keyframe, count] : votes) {
    if (keyframe->bad) continue;
    add(keyframe);
    if (count > best_votes) {
      best_votes = count;
      best = keyframe;
    }
  }
  // Neighbours of the voted keyframes extend the local map to what the camera may see next.
  const std::size_t voted = local_keyframes_.size();
  for (std::size_t k = 0; k < voted; ++k) {
    if (local_keyframes_.size() >= static_cast<std::size_t>(options_.max_local_keyframes)) break;
    auto keyframe = local_keyframes_[k];
    for (map::KeyFrame* neighbour : keyframe->bestCovisibles(10)) add(neighbour);
    for (map::KeyFrame* child : keyframe->children) add(child);
    add(keyframe->parent);
  }
  if (best) {
    reference_keyframe_ = best->shared_from_this();
    current_.reference_keyframe = reference_keyframe_;
  }
}

void Tracker::updateLocalPoints() {
  local_points_.clear();
  for (const auto& keyframe : local_keyframes_) {
    for (const auto& [index, point] : keyframe->validMapPoints()) {
      if (point->local_map_search == local_map_searches_) continue;
      point->local_map_search = local_map_searches_;
      local_points_.push_back(point);
    }
  }
}

int Tracker::searchLocalMap() {
  for (const auto& point : current_.map_points) {
    if (!point || point->bad) continue;
    point->increaseVisible();
    point->seen_in_search = local_map_searches_;
  }
  std::vector<ProjectedPoint> projections;
  for (const auto& point : local_points_) {
    if (point->bad || point->seen_in_search == local_map_searches_) continue;
    auto projected = projectIntoFrame(point, current_, 0.5);
    if (!projected) continue;
    point->increaseVisible();
    projections.push_back(std::move(*projected));
  }
  if (projections.empty()) return 0;
  const bool recently_relocalised =
      last_relocalisation_frame_id_ > 0 && current_.id < last_relocalisation_frame_id_ + 2;
  return searchLocalPoints(
      current_, projections,
      recently_relocalised ? kLocalMapRadiusAfterRelocalisation : kLocalMapRadius);
}

void Tracker::rememberPose() {
  recent_poses_.emplace_back(current_.id, current_.T_cw);
  while (recent_poses_.size() > static_cast<std::size_t>(options_.late_mask_max_age)) {
    recent_poses_.pop_front();
  }
}

int Tracker::cullPointsOnLateMask(std::uint64_t frame_id, const cv::Mat& dynamic_mask,
                                  const cv::Mat& depth_m) {
  if (options_.localize_only) return 0;
  const auto pose = std::find_if(recent_poses_.begin(), recent_poses_.end(),
                                 [&](const auto& entry) { return entry.first == frame_id; });
  if (pose == recent_poses_.end()) return 0;
  const auto on_surface = pointsOnDynamicSurface(local_points_, pose->second, *current_.camera,
                                                 dynamic_mask, depth_m, options_.late_mask);
  for (const auto& point : on_surface) point->setBad();
  return static_cast<int>(on_surface.size());
}

void Tracker::cullPointsSeenThrough() {
  if (options_.seen_through_frames_to_cull <= 0) return;
  const auto seen_through = pointsSeenThrough(local_points_, current_, options_.free_space);
  spdlog::debug("frame {}: {} of {} local points seen through, {} inliers", current_.id,
                seen_through.size(), local_points_.size(), inliers_);
  for (const auto& point : seen_through) {
    if (++point->seen_through >= options_.seen_through_frames_to_cull) point->setBad();
  }
}

int Tracker::trackedOfReference() const {
  int tracked = 0;
  for (const auto& point : current_.map_points) {
    if (point && !point->bad && point->isObservedBy(reference_keyframe_.get())) ++tracked;
  }
  return tracked;
}

bool Tracker::needNewKeyFrame() const {
  KeyFrameEvidence evidence;
  evidence.inliers = inliers_;
  evidence.checked_inliers = checkedMatches();
  evidence.local_map_checked =
      std::any_of(local_points_.begin(), local_points_.end(),
                  [](const auto& point) { return !point->bad && !point->provisional; });
  evidence.tracked_share = reference_overlap_.share();
  for (std::size_t i = 0; i < current_.size(); ++i) {
    if (current_.depth[i] <= 0.0f || current_.depth[i] >= current_.camera->close_depth_m) {
      continue;
    }
    ++(hasMapPoint(current_, i) ? evidence.tracked_close : evidence.untracked_close);
  }
  evidence.frames_since_keyframe = current_.id - last_keyframe_frame_id_;
  evidence.mapping_idle = sink_.isIdle();
  evidence.queued_keyframes = sink_.queuedKeyFrames();
  spdlog::debug(
      "frame {}: reference keyframe {}: {} of {} points tracked, close {} / {}, {} of {} inliers "
      "checked, mapping {}",
      current_.id, reference_keyframe_->id, reference_overlap_.tracked(), reference_overlap_.best(),
      evidence.tracked_close, evidence.untracked_close, evidence.checked_inliers, evidence.inliers,
      evidence.mapping_idle ? "idle" : "busy");
  return needsKeyFrame(evidence, options_.keyframes);
}

void Tracker::createKeyFrame() {
  auto keyframe = map_.createKeyFrame(current_);
  for (std::size_t i = 0; i < current_.size(); ++i) {
    if (!hasMapPoint(current_, i)) continue;
    keyframe->addMapPoint(current_.map_points[i], i);
    current_.map_points[i]->addObservation(keyframe.get(), i);
  }
  addNewMapPoints(*keyframe);
  reference_keyframe_ = keyframe;
  current_.reference_keyframe = keyframe;
  last_keyframe_ = keyframe;
  last_keyframe_frame_id_ = current_.id;
  if (keyframe_database_) keyframe_database_->add(keyframe);
  sink_.insertKeyFrame(keyframe);
}

void Tracker::addNewMapPoints(map::KeyFrame& keyframe) {
  const double max_depth = current_.camera->close_depth_m * options_.new_point_depth_factor;
  int created_or_tracked = 0;
  for (std::size_t i : keypointsByDepth(current_)) {
    if (hasMapPoint(current_, i)) {
      ++created_or_tracked;
    } else {
      auto point = map_.createMapPoint(keyframe.unproject(i), &keyframe);
      point->provisional = true;
      point->addObservation(&keyframe, i);
      keyframe.addMapPoint(point, i);
      point->updateDescriptor();
      point->updateNormalAndDepth();
      current_.map_points[i] = point;
      ++created_or_tracked;
    }
    if (current_.depth[i] > max_depth &&
        created_or_tracked > options_.min_new_points_per_keyframe) {
      break;
    }
  }
}

void Tracker::dropTemporaryPoints() {
  for (auto& point : current_.map_points) {
    if (point && point->numObservations() == 0) point.reset();
  }
  temporary_points_.clear();
}

void Tracker::reanchorLastFrame() {
  // The map moved under the last frame (loop correction): its pose follows its reference
  // keyframe, so the motion model predicts the current frame in the corrected map.
  if (!last_.has_pose || records_.empty()) return;
  const FramePoseRecord& record = records_.back();
  if (record.reference != last_.reference_keyframe.get() || record.reference->bad) return;
  last_.T_cw = record.T_c_reference() * record.reference->T_cw;
}

void Tracker::recordPose() {
  // A frame whose points no live keyframe observes (matched to visual-odometry points only, the
  // keyframes that saw the rest culled) gets no reference from the local map's vote
  // (updateLocalKeyFrames): it is placed relative to the tracker's reference.
  if (!current_.reference_keyframe) current_.reference_keyframe = reference_keyframe_;
  const auto& reference = current_.reference_keyframe;
  records_.emplace_back(current_.timestamp, reference.get(),
                        current_.T_cw * reference->T_cw.inverse());
}

Tracker::FramePoseRecord::FramePoseRecord(double timestamp, map::KeyFrame* reference,
                                          const geometry::Pose& T_c_reference)
    : timestamp(timestamp),
      reference(reference),
      rotation_(T_c_reference.linear()),
      translation_(T_c_reference.translation()) {}

static_assert(sizeof(Tracker::FramePoseRecord) == 72);

geometry::Pose Tracker::FramePoseRecord::T_c_reference() const {
  return geometry::poseFromTranslationQuaternion(translation_, rotation_);
}

}  // namespace segslam::tracking
