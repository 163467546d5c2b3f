#include "segslam/segmentation/mask_stream.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "segslam/util/elapsed_time.h"
#include "segslam/util/thread_priority.h"

namespace segslam::segmentation {

MaskStream::MaskStream(Segment segment, MaskStreamOptions options,
                       std::shared_ptr<MaskPropagator> propagator)
    : segment_(std::move(segment)),
      options_(options),
      propagator_(propagator ? std::move(propagator) : std::make_shared<MaskPropagator>()) {
  if (options_.interval < 1) options_.interval = 1;
  if (options_.busy_interval < 1) options_.busy_interval = 1;
  if (!options_.synchronous) thread_ = std::thread([this] { work(); });
}

MaskStream::~MaskStream() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void MaskStream::work() {
  util::lowerThisThreadsPriority(options_.thread_niceness);
  while (true) {
    SegmentationJob job;
    bool keyframe = false;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(
          lock, [this] { return stopping_ || pending_.has_value() || !keyframe_jobs_.empty(); });
      if (stopping_) return;
      keyframe = !keyframe_jobs_.empty();
      if (keyframe) {
        job = std::move(keyframe_jobs_.front());
        keyframe_jobs_.pop_front();
      } else {
        job = std::move(*pending_);
        pending_.reset();
      }
      busy_ = true;
    }
    Result result = run(job);
    result.keyframe = keyframe;
    {
      std::lock_guard lock(mutex_);
      finished_.push_back(std::move(result));
      busy_ = false;
    }
    changed_.notify_all();
  }
}

MaskStream::Result MaskStream::run(const SegmentationJob& job) {
  const auto start = std::chrono::steady_clock::now();
  SemanticMasks masks = segment_(job);
  const double ms = util::millisecondsSince(start);
  {
    std::lock_guard lock(mutex_);
    ++runs_;
    total_ms_ += ms;
  }
  const bool undecided = masks.dynamic.empty();
  if (undecided) masks.dynamic = cv::Mat::zeros(job.current.bgr.size(), CV_8UC1);
  if (masks.labels.empty()) masks.labels = masks.dynamic.clone();
  std::vector<float> depths = objectDepths(masks.dynamic, job.current.depth, options_.refinement);
  return {job.current.id, undecided, false, std::move(masks), std::move(depths), job.current.depth};
}

void MaskStream::submit(SegmentationJob job) {
  if (!segmenterWanted(job.current.id)) return;
  {
    std::lock_guard lock(mutex_);
    if (busy_ || pending_ || !keyframe_jobs_.empty()) return;
    // The frames are shared (the caller writes no more into them); the mask of another method is
    // copied, as its owner may still add to it.
    pending_ = SegmentationJob{job.previous, job.current, job.known_dynamic.clone()};
  }
  last_submitted_ = job.current.id;
  changed_.notify_all();
}

bool MaskStream::segmenterWanted(std::uint64_t frame_id) const {
  if (!last_submitted_ || tracking_busy_share_.load() < options_.busy_share_limit) return true;
  return frame_id >= *last_submitted_ + static_cast<std::uint64_t>(options_.busy_interval);
}

SemanticMasks MaskStream::masksFor(std::uint64_t frame_id, const cv::Mat& bgr, const cv::Mat& depth,
                                   const cv::Mat& known_dynamic) {
  propagator_->addFrame(frame_id, bgr);
  SegmentationJob job{previous_, StreamFrame{frame_id, bgr, depth}, known_dynamic};
  if (options_.synchronous) {
    segmentSynchronously(job);
  } else {
    submit(job);
    collectFinished(frame_id);
  }
  previous_ = job.current;
  SemanticMasks masks = carryLatest(frame_id, bgr.size());
  masks.dynamic = fitToObjects(masks.dynamic, depth, frame_id);
  if (options_.border_linger_frames > 0) {
    const cv::Mat lingering = lingeringObjects(masks.dynamic, depth, frame_id);
    if (!lingering.empty()) masks.dynamic |= lingering;
  }
  return masks;
}

void MaskStream::collectFinished(std::uint64_t frame_id) {
  std::unique_lock lock(mutex_);
  if (!latest_ && finished_.empty()) {
    changed_.wait(lock, [this] { return !finished_.empty(); });
  }
  std::vector<Result> finished = std::move(finished_);
  finished_.clear();
  lock.unlock();
  for (Result& result : finished) collect(std::move(result), frame_id);
}

void MaskStream::segmentSynchronously(const SegmentationJob& job) {
  const std::uint64_t frame_id = job.current.id;
  if (!last_synchronous_run_ ||
      frame_id - *last_synchronous_run_ >= static_cast<std::uint64_t>(options_.interval)) {
    last_synchronous_run_ = frame_id;
    delayed_.push_back(run(job));
  }
  // The first output is used at once, as the threaded stream waits for it.
  const auto latency = static_cast<std::uint64_t>(options_.latency_frames);
  while (!delayed_.empty() && (!latest_ || delayed_.front().frame_id + latency <= frame_id)) {
    collect(std::move(delayed_.front()), frame_id);
    delayed_.pop_front();
  }
}

void MaskStream::segmentKeyFrame(std::uint64_t frame_id, const cv::Mat& bgr, const cv::Mat& depth) {
  if (latest_ && latest_->frame_id == frame_id) {
    late_.push_back(lateOutput(*latest_, true));
    return;
  }
  keyframes_asked_.insert(frame_id);
  const bool on_its_way = last_submitted_ == frame_id || last_synchronous_run_ == frame_id;
  if (on_its_way) return;
  SegmentationJob job{StreamFrame{}, StreamFrame{frame_id, bgr, depth}, cv::Mat()};
  if (options_.synchronous) {
    // A keyframe's output takes the place of the next scheduled one, as the network's thread
    // would be busy with it; it is the newest frame, so `delayed_` stays in frame order.
    last_synchronous_run_ = frame_id;
    delayed_.push_back(run(job));
    return;
  }
  {
    std::lock_guard lock(mutex_);
    keyframe_jobs_.push_back(std::move(job));
    while (keyframe_jobs_.size() > options_.max_queued_keyframes) {
      keyframes_asked_.erase(keyframe_jobs_.front().current.id);
      keyframe_jobs_.pop_front();
    }
  }
  changed_.notify_all();
}

void MaskStream::collect(Result result, std::uint64_t frame_id) {
  if (keyframes_asked_.erase(result.frame_id) > 0) {
    late_.push_back(lateOutput(result, true));
  } else if (result.frame_id < frame_id) {
    late_.push_back(lateOutput(result, false));
  }
  if (result.undecided && latest_) return;
  // Keyframe jobs jump the queue, so outputs need not come in frame order: the newest is carried.
  if (!latest_ || result.frame_id > latest_->frame_id) latest_ = std::move(result);
}

LateOutput MaskStream::lateOutput(const Result& result, bool keyframe) const {
  LateOutput late{result.frame_id, result.masks.dynamic,
                  options_.carry_labels ? result.masks.labels : cv::Mat(), result.depth, keyframe};
  if (options_.refine_fresh_masks && !result.depth.empty() && cv::countNonZero(late.dynamic) > 0) {
    late.dynamic = refineMaskByDepth(late.dynamic, result.depth, options_.min_band_px,
                                     result.object_depths, options_.refinement);
  }
  return late;
}

std::vector<LateOutput> MaskStream::takeRemainingOutputs() {
  constexpr std::uint64_t kAfterEveryFrame = std::numeric_limits<std::uint64_t>::max();
  for (Result& result : delayed_) collect(std::move(result), kAfterEveryFrame);
  delayed_.clear();
  std::vector<Result> finished;
  {
    std::lock_guard lock(mutex_);
    finished = std::move(finished_);
    finished_.clear();
  }
  for (Result& result : finished) collect(std::move(result), kAfterEveryFrame);
  return takeLateOutputs();
}

std::vector<LateOutput> MaskStream::takeLateOutputs() {
  std::vector<LateOutput> late = std::move(late_);
  late_.clear();
  return late;
}

SemanticMasks MaskStream::carryLatest(std::uint64_t frame_id, cv::Size size) {
  if (!carried_ || carried_->source_id != latest_->frame_id) {
    carried_ = Carried{latest_->frame_id, latest_->frame_id, latest_->masks};
  }
  SemanticMasks masks{options_.carry_labels
                          ? propagator_->propagate(carried_->masks.labels, carried_->frame_id)
                          : cv::Mat(),
                      propagator_->moveObjects(carried_->masks.dynamic, carried_->frame_id)};
  if (masks.labels.empty() && options_.carry_labels) masks.labels = cv::Mat::zeros(size, CV_8UC1);
  if (masks.dynamic.empty()) masks.dynamic = cv::Mat::zeros(size, CV_8UC1);
  carried_->frame_id = frame_id;
  carried_->masks = masks;
  return {masks.labels.clone(), masks.dynamic.clone()};
}

namespace {

// The connected parts of `mask` that touch the image border and that `other` covers less than a
// fifth of.
cv::Mat borderPartsOutside(const cv::Mat& mask, const cv::Mat& other) {
  cv::Mat labels;
  cv::Mat stats;
  cv::Mat centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  cv::Mat parts = cv::Mat::zeros(mask.size(), CV_8UC1);
  for (int label = 1; label < count; ++label) {
    const int x = stats.at<int>(label, cv::CC_STAT_LEFT);
    const int y = stats.at<int>(label, cv::CC_STAT_TOP);
    const int right = x + stats.at<int>(label, cv::CC_STAT_WIDTH);
    const int bottom = y + stats.at<int>(label, cv::CC_STAT_HEIGHT);
    if (x > 0 && y > 0 && right < mask.cols && bottom < mask.rows) continue;
    const cv::Mat part = labels == label;
    const int area = stats.at<int>(label, cv::CC_STAT_AREA);
    if (5 * cv::countNonZero(part & other) < area) parts |= part;
  }
  return parts;
}

bool touchesBorder(const cv::Mat& mask) {
  return cv::countNonZero(mask.row(0)) + cv::countNonZero(mask.row(mask.rows - 1)) +
             cv::countNonZero(mask.col(0)) + cv::countNonZero(mask.col(mask.cols - 1)) >
         0;
}

}  // namespace

cv::Mat MaskStream::lingeringObjects(const cv::Mat& fitted, const cv::Mat& depth,
                                     std::uint64_t frame_id) {
  if (lingering_) {
    cv::Mat moved = propagator_->moveObjects(lingering_->dynamic, lingering_->frame_id);
    if (!moved.empty() && !depth.empty()) {
      // Snapped to the object's depth as a carried output is. A lost object's mask that grows
      // well beyond its area has joined a larger surface at its depth (the desk the person
      // stood in front of): the person is gone. (The lost part may be a little short of the
      // object, hence the margin.)
      DepthRefinementOptions merging = options_.refinement;
      merging.keep_masked_part_of_joined_objects = false;
      moved = refineMaskByDepth(moved, depth, options_.growth_px_per_frame + options_.min_band_px,
                                lingering_->object_depths, merging);
      if (2 * cv::countNonZero(moved) > 3 * lingering_->area) moved = cv::Mat();
    }
    lingering_->frame_id = frame_id;
    lingering_->dynamic = moved.empty() ? moved : cv::Mat(moved & ~fitted);
    if (moved.empty() ||
        frame_id - lingering_->seen_id >
            static_cast<std::uint64_t>(options_.border_linger_frames) ||
        !touchesBorder(lingering_->dynamic)) {
      lingering_.reset();
    }
  }
  if (last_fitted_ && last_fitted_->source_id != latest_->frame_id) {
    addLostObjects(fitted, depth, frame_id);
  }
  last_fitted_ = Carried{latest_->frame_id, frame_id, {cv::Mat(), fitted.clone()}};
  return lingering_ ? lingering_->dynamic : cv::Mat();
}

void MaskStream::addLostObjects(const cv::Mat& fitted, const cv::Mat& depth,
                                std::uint64_t frame_id) {
  const cv::Mat before =
      propagator_->moveObjects(last_fitted_->masks.dynamic, last_fitted_->frame_id);
  if (before.empty()) return;
  const cv::Mat lost = borderPartsOutside(before, fitted);
  if (cv::countNonZero(lost) == 0) return;
  if (lingering_) {
    lingering_->dynamic |= lost;
    lingering_->area += cv::countNonZero(lost);
    return;
  }
  lingering_ = Lingering{last_fitted_->source_id, frame_id, lost,
                         objectDepths(lost, depth, options_.refinement), cv::countNonZero(lost)};
}

cv::Mat MaskStream::fitToObjects(const cv::Mat& dynamic, const cv::Mat& depth,
                                 std::uint64_t frame_id) const {
  // Optical flow follows textured objects; on plain clothing it mostly sees the background move,
  // so an old mask falls behind a walking person. The person is searched for around the mask, as
  // far as it can have moved since the segmenter saw it.
  const std::uint64_t age = frame_id - latest_->frame_id;
  const int lag = static_cast<int>(
      std::min<std::uint64_t>(age * options_.growth_px_per_frame, options_.max_growth_px));
  if (cv::countNonZero(dynamic) == 0) return dynamic;
  if (age == 0 && !options_.refine_fresh_masks) return dynamic;
  if (!depth.empty()) {
    return refineMaskByDepth(dynamic, depth, lag + options_.min_band_px, latest_->object_depths,
                             options_.refinement);
  }
  if (lag == 0) return dynamic;
  cv::Mat grown;
  cv::dilate(dynamic, grown,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * lag + 1, 2 * lag + 1)));
  return grown;
}

void MaskStream::setTrackingBusyShare(double share) { tracking_busy_share_.store(share); }

int MaskStream::runs() const {
  std::lock_guard lock(mutex_);
  return runs_;
}

double MaskStream::meanRunMilliseconds() const {
  std::lock_guard lock(mutex_);
  return runs_ > 0 ? total_ms_ / runs_ : 0.0;
}

}  // namespace segslam::segmentation
