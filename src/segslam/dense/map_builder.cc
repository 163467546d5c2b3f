#include "segslam/dense/map_builder.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

namespace segslam::dense {

MapBuilder::MapBuilder(const core::Camera& camera, MapBuilderOptions options)
    : maker_(camera, options.keyframe), options_(options), worker_([this] { work(); }) {
  // Objects are only found when neighbouring voxels can be within the clustering distance.
  options_.objects.cluster_distance =
      std::max(options_.objects.cluster_distance, 3.0 * options_.keyframe.voxel_size);
}

MapBuilder::~MapBuilder() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void MapBuilder::addKeyFrame(std::uint64_t id, double timestamp, KeyFrameImages images) {
  {
    std::lock_guard lock(mutex_);
    queue_.push_back({id, timestamp, std::move(images)});
  }
  changed_.notify_all();
}

void MapBuilder::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return queue_.empty() && !busy_; });
  if (error_) std::rethrow_exception(error_);
}

void MapBuilder::work() {
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, nothing left
    QueuedKeyFrame keyframe = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    lock.unlock();
    const auto start = std::chrono::steady_clock::now();
    KeyFrameCloud cloud;
    std::exception_ptr error;
    try {
      cloud = maker_.make(keyframe.images);
    } catch (...) {
      error = std::current_exception();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    if (error && !error_) error_ = error;
    if (!error) clouds_[keyframe.timestamp] = {keyframe.id, std::move(cloud)};
    keyframe_seconds_ += seconds;
    busy_ = false;
    changed_.notify_all();
  }
}

LabelledCloud MapBuilder::worldCloud(const core::Trajectory& keyframe_poses, bool dynamic) const {
  LabelledCloud world;
  for (const auto& pose : keyframe_poses.poses()) {
    const auto it = clouds_.lower_bound(pose.timestamp - 1e-4);
    if (it == clouds_.end() || it->first > pose.timestamp + 1e-4) continue;
    const KeyFrameCloud& cloud = it->second.cloud;
    world.append(transformed(dynamic ? cloud.dynamic_points : cloud.static_points, pose.T_wc));
  }
  return voxelDownsample(world, options_.keyframe.voxel_size);
}

DenseMap MapBuilder::build(const core::Trajectory& keyframe_poses) {
  finish();
  std::lock_guard lock(mutex_);
  DenseMap map;
  map.voxel_size = options_.keyframe.voxel_size;
  auto start = std::chrono::steady_clock::now();
  const auto lap = [&start](const char* step) {
    const auto now = std::chrono::steady_clock::now();
    spdlog::debug("dense map: {} {:.3f} s", step,
                  std::chrono::duration<double>(now - start).count());
    start = now;
  };
  LabelledCloud static_points = worldCloud(keyframe_poses, false);
  lap("merging");
  map.static_points = removeOutliers(static_points, options_.cleaning);
  lap("outlier removal");
  map.dynamic_points = worldCloud(keyframe_poses, true);
  map.objects = clusterObjects(map.static_points, options_.objects);
  lap("objects");
  auto dynamic_objects = dynamicObjects(map.dynamic_points, options_.objects);
  numberAfter(map.objects, dynamic_objects);
  std::move(dynamic_objects.begin(), dynamic_objects.end(), std::back_inserter(map.objects));
  return map;
}

std::size_t MapBuilder::numKeyFrames() {
  finish();
  std::lock_guard lock(mutex_);
  return clouds_.size();
}

double MapBuilder::keyFrameSeconds() {
  std::lock_guard lock(mutex_);
  return keyframe_seconds_;
}

}  // namespace segslam::dense
