#include "segslam/dense/map_builder.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <map>
#include <vector>

#include "segslam/dense/keyframe_fold.h"
#include "segslam/dense/seen_through.h"
#include "segslam/util/thread_priority.h"

namespace segslam::dense {

MapBuilder::MapBuilder(const core::Camera& camera, MapBuilderOptions options)
    : camera_(camera), maker_(camera, options.keyframe), options_(options) {
  // Views of one surface share cells only when a cell holds more than one voxel.
  options_.objects.cell_size =
      std::max(options_.objects.cell_size, 2.0 * options_.keyframe.voxel_size);
  if (!options_.synchronous) worker_ = std::thread([this] { work(); });
}

MapBuilder::~MapBuilder() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void MapBuilder::addKeyFrame(std::uint64_t id, double timestamp, KeyFrameImages images) {
  {
    std::unique_lock lock(mutex_);
    queue_.push_back({id, timestamp, std::move(images)});
    if (options_.synchronous) makeFront(lock);
  }
  changed_.notify_all();
}

void MapBuilder::setLiveKeyFrames(core::Trajectory live) {
  {
    std::unique_lock lock(mutex_);
    // Poses are noted at once: a keyframe culled before the map thread folds is still placed.
    for (const auto& pose : live.poses()) {
      const auto it = clouds_.lower_bound(pose.timestamp - 1e-4);
      if (it != clouds_.end() && it->first <= pose.timestamp + 1e-4) {
        it->second.T_wc = pose.T_wc;
      } else {
        poses_before_cloud_[pose.timestamp] = pose.T_wc;
      }
    }
    pending_live_ = std::move(live);
    if (options_.synchronous) foldPending(lock);
  }
  changed_.notify_all();
}

void MapBuilder::setEarlierMap(LabelledCloud static_points) {
  std::lock_guard lock(mutex_);
  earlier_ = std::move(static_points);
}

void MapBuilder::finish() {
  std::unique_lock lock(mutex_);
  // What is still queued is made here rather than by the map thread: that thread runs at a low
  // priority, and now nothing else is waiting for the CPU.
  while (!queue_.empty()) makeFront(lock);
  changed_.wait(lock, [this] { return queue_.empty() && working_ == 0; });
  if (pending_live_) foldPending(lock);
  if (error_) std::rethrow_exception(error_);
}

bool MapBuilder::foldDue() const { return pending_live_ && working_ == 0; }

void MapBuilder::foldPending(std::unique_lock<std::mutex>& lock) {
  const core::Trajectory live = std::move(*pending_live_);
  pending_live_.reset();
  foldCulled(live, true, lock);
}

void MapBuilder::work() {
  util::lowerThisThreadsPriority(options_.thread_niceness);
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [this] { return stopping_ || !queue_.empty() || foldDue(); });
    if (!queue_.empty()) {
      makeFront(lock);
    } else if (foldDue()) {
      foldPending(lock);
    } else {
      return;  // stopping, nothing left
    }
  }
}

void MapBuilder::makeFront(std::unique_lock<std::mutex>& lock) {
  QueuedKeyFrame keyframe = std::move(queue_.front());
  queue_.pop_front();
  ++working_;
  lock.unlock();
  const double start = util::thisThreadCpuSeconds();
  double projected = start;
  KeyFrameCloud cloud;
  std::exception_ptr error;
  try {
    cloud = maker_.backProject(keyframe.images);
    projected = util::thisThreadCpuSeconds();
    cloud = maker_.downsample(cloud);
  } catch (...) {
    error = std::current_exception();
  }
  const double end = util::thisThreadCpuSeconds();
  lock.lock();
  if (error && !error_) error_ = error;
  if (!error) {
    std::optional<geometry::Pose> pose;
    if (const auto it = poses_before_cloud_.find(keyframe.timestamp);
        it != poses_before_cloud_.end()) {
      pose = it->second;
      poses_before_cloud_.erase(it);
    }
    clouds_[keyframe.timestamp] = {keyframe.id, PackedKeyFrameCloud(cloud), pose};
  }
  timings_.back_projection += projected - start;
  timings_.keyframe_voxels += end - projected;
  --working_;
  changed_.notify_all();
}

void MapBuilder::foldCulled(const core::Trajectory& live, bool only_older,
                            std::unique_lock<std::mutex>& lock) {
  if (live.empty()) return;
  const double newest = live.poses().back().timestamp;
  Clouds culled;
  Clouds targets;
  for (auto it = clouds_.begin(); it != clouds_.end();) {
    const std::optional<geometry::Pose> pose = live.poseAt(it->first, 1e-4);
    if (pose) it->second.T_wc = *pose;
    const bool gone = !pose && (!only_older || it->first < newest);
    const bool is_culled = gone && it->second.T_wc;
    if (gone && !is_culled) {
      it = clouds_.erase(it);  // culled before any pose of it came: where it was is unknown
    } else if (pose || is_culled) {
      (is_culled ? culled : targets).insert(clouds_.extract(it++));
    } else {
      ++it;
    }
  }
  if (culled.empty() || targets.empty()) {
    clouds_.merge(culled);
    clouds_.merge(targets);
    return;
  }
  ++working_;
  lock.unlock();
  std::vector<Eigen::Isometry3d> target_poses;
  std::vector<StoredCloud*> target_clouds;
  for (auto& [timestamp, stored] : targets) {
    target_poses.push_back(*stored.T_wc);
    target_clouds.push_back(&stored);
  }
  std::map<StoredCloud*, std::vector<const StoredCloud*>> folded_into;
  for (const auto& [timestamp, stored] : culled) {
    folded_into[target_clouds[nearestView(*stored.T_wc, target_poses)]].push_back(&stored);
  }
  for (const auto& [target, sources] : folded_into) {
    KeyFrameCloud cloud = target->cloud.unpacked();
    for (const StoredCloud* source : sources) {
      foldInto(cloud, *target->T_wc, source->cloud.unpacked(), *source->T_wc,
               options_.keyframe.voxel_size, camera_);
    }
    target->cloud = PackedKeyFrameCloud(cloud);
  }
  lock.lock();
  clouds_.merge(targets);
  --working_;
  changed_.notify_all();
}

MapBuilder::WorldClouds MapBuilder::worldClouds(const core::Trajectory& keyframe_poses,
                                                ObjectMapBuilder& objects,
                                                const KeyFrameScanSink& scans) const {
  WorldClouds world;
  // The clouds unpacked, kept only while an earlier map needs them for its free-space views.
  std::deque<KeyFrameCloud> unpacked;
  std::vector<std::pair<Eigen::Isometry3d, const KeyFrameCloud*>> views;
  for (const auto& pose : keyframe_poses.poses()) {
    const auto it = clouds_.lower_bound(pose.timestamp - 1e-4);
    if (it == clouds_.end() || it->first > pose.timestamp + 1e-4) continue;
    if (!earlier_) unpacked.clear();
    const KeyFrameCloud& cloud = unpacked.emplace_back(it->second.cloud.unpacked());
    if (earlier_) views.emplace_back(pose.T_wc, &cloud);
    const LabelledCloud static_points = transformed(cloud.static_points, pose.T_wc);
    const LabelledCloud dynamic_points = transformed(cloud.dynamic_points, pose.T_wc);
    const auto start = std::chrono::steady_clock::now();
    objects.addKeyFrame(it->second.id, pose.timestamp, pose.T_wc, static_points, dynamic_points);
    world.object_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    LabelledCloud seen = static_points;
    seen.append(transformed(cloud.folded_points, pose.T_wc));
    if (scans) {
      const auto scan_start = std::chrono::steady_clock::now();
      scans(pose.T_wc.translation(), seen, dynamic_points);
      world.scan_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - scan_start).count();
    }
    world.static_points.append(seen);
    world.dynamic_points.append(dynamic_points);
  }
  if (earlier_) {
    const LabelledCloud kept = withoutSeenThrough(*earlier_, camera_, views);
    world.earlier_points_removed = earlier_->size() - kept.size();
    world.static_points.append(kept);
  }
  const double voxel = options_.keyframe.voxel_size;
  return {voxelDownsample(world.static_points, voxel), voxelDownsample(world.dynamic_points, voxel),
          world.object_seconds, world.scan_seconds, world.earlier_points_removed};
}

DenseMap MapBuilder::build(const core::Trajectory& keyframe_poses, const KeyFrameScanSink& scans) {
  finish();
  std::unique_lock lock(mutex_);
  foldCulled(keyframe_poses, false, lock);
  DenseMap map;
  map.voxel_size = options_.keyframe.voxel_size;
  auto start = std::chrono::steady_clock::now();
  const auto lap = [&start](double& seconds) {
    const auto now = std::chrono::steady_clock::now();
    seconds = std::chrono::duration<double>(now - start).count();
    start = now;
  };
  ObjectMapBuilder objects(camera_, options_.keyframe.max_depth, options_.objects);
  WorldClouds world = worldClouds(keyframe_poses, objects, scans);
  map.earlier_points_removed = world.earlier_points_removed;
  map.dynamic_points = std::move(world.dynamic_points);
  lap(timings_.merging);
  map.static_points = removeOutliers(world.static_points, options_.cleaning);
  lap(timings_.outlier_removal);
  map.objects = objects.objects(map.static_points, map.voxel_size);
  lap(timings_.objects);
  timings_.merging -= world.object_seconds + world.scan_seconds;
  timings_.objects += world.object_seconds;
  timings_.scans = world.scan_seconds;
  spdlog::debug("dense map: merging {:.3f} s, outlier removal {:.3f} s, objects {:.3f} s",
                timings_.merging, timings_.outlier_removal, timings_.objects);
  return map;
}

std::size_t MapBuilder::numKeyFrames() {
  finish();
  std::lock_guard lock(mutex_);
  return clouds_.size();
}

MapTimings MapBuilder::timings() {
  std::lock_guard lock(mutex_);
  return timings_;
}

}  // namespace segslam::dense
