#include "segslam/segmentation/semantic_mask_stream.h"

#include <algorithm>
#include <chrono>
#include <opencv2/imgproc.hpp>

namespace segslam::segmentation {

SemanticMaskStream::SemanticMaskStream(SemanticSegmenter segmenter, MaskStreamOptions options)
    : segmenter_(std::move(segmenter)),
      options_(options),
      dynamic_indices_(segmenter_.config().dynamicClassIndices()) {
  if (options_.interval < 1) options_.interval = 1;
  if (!options_.synchronous) thread_ = std::thread([this] { work(); });
}

SemanticMaskStream::~SemanticMaskStream() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void SemanticMaskStream::work() {
  while (true) {
    std::pair<std::uint64_t, cv::Mat> job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
      if (stopping_) return;
      job = std::move(*pending_);
      pending_.reset();
      busy_ = true;
    }
    const auto start = std::chrono::steady_clock::now();
    SemanticMasks masks = segmenter_.segment(job.second);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    {
      std::lock_guard lock(mutex_);
      finished_ = Result{job.first, std::move(masks.labels)};
      busy_ = false;
      ++runs_;
      total_ms_ += ms;
    }
    changed_.notify_all();
  }
}

void SemanticMaskStream::submit(std::uint64_t frame_id, const cv::Mat& bgr) {
  {
    std::lock_guard lock(mutex_);
    if (busy_ || pending_) return;
    pending_ = std::make_pair(frame_id, bgr.clone());
  }
  changed_.notify_all();
}

void SemanticMaskStream::segmentNow(std::uint64_t frame_id, const cv::Mat& bgr) {
  const auto start = std::chrono::steady_clock::now();
  latest_ = Result{frame_id, segmenter_.segment(bgr).labels};
  std::lock_guard lock(mutex_);
  ++runs_;
  total_ms_ +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

SemanticMasks SemanticMaskStream::masksFor(std::uint64_t frame_id, const cv::Mat& bgr) {
  propagator_.addFrame(frame_id, bgr);
  if (options_.synchronous) {
    if (!latest_ || frame_id - latest_->frame_id >= static_cast<std::uint64_t>(options_.interval)) {
      segmentNow(frame_id, bgr);
    }
  } else {
    submit(frame_id, bgr);
    std::unique_lock lock(mutex_);
    if (!latest_ && !finished_) {
      changed_.wait(lock, [this] { return finished_.has_value(); });
    }
    if (finished_) {
      latest_ = std::move(finished_);
      finished_.reset();
    }
  }
  cv::Mat labels = propagator_.propagate(latest_->labels, latest_->frame_id);
  if (labels.empty()) labels = cv::Mat::zeros(bgr.size(), CV_8UC1);
  SemanticMasks masks = masksFromLabels(labels);
  growWithAge(masks.dynamic, frame_id - latest_->frame_id);
  return masks;
}

void SemanticMaskStream::growWithAge(cv::Mat& dynamic, std::uint64_t age) const {
  // Optical flow follows textured objects; on plain clothing it mostly sees the background move,
  // so an old mask falls behind a walking person. Growing it with its age keeps the person
  // covered until the network's next output.
  const int radius = static_cast<int>(
      std::min<std::uint64_t>(age * options_.growth_px_per_frame, options_.max_growth_px));
  if (radius <= 0 || cv::countNonZero(dynamic) == 0) return;
  cv::dilate(
      dynamic, dynamic,
      cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1)));
}

SemanticMasks SemanticMaskStream::masksFromLabels(const cv::Mat& labels) const {
  SemanticMasks masks{labels, cv::Mat::zeros(labels.size(), CV_8UC1)};
  for (int index : dynamic_indices_) masks.dynamic.setTo(255, labels == index);
  return masks;
}

int SemanticMaskStream::networkRuns() const {
  std::lock_guard lock(mutex_);
  return runs_;
}

double SemanticMaskStream::meanNetworkMilliseconds() const {
  std::lock_guard lock(mutex_);
  return runs_ > 0 ? total_ms_ / runs_ : 0.0;
}

}  // namespace segslam::segmentation
