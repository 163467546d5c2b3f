#pragma once

#include <cstdint>
#include <deque>
#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>
#include <optional>

namespace segslam::segmentation {

// Carries a per-pixel label image from the frame it was computed on to a later frame by dense
// optical flow (DIS), so that frames between two runs of a slow segmentation network still get
// a mask that follows both the camera and the moving objects. Flow is computed at a reduced
// resolution, one field per frame, and kept for the last `history` frames.
class MaskPropagator {
 public:
  explicit MaskPropagator(int history = 30, double flow_scale = 0.5);

  // Adds the newest frame (CV_8UC3 BGR or CV_8UC1) and computes the flow back to the previous one.
  // Adding the newest frame again does nothing, so that several users can share one propagator.
  void addFrame(std::uint64_t frame_id, const cv::Mat& image);

  // `labels` (CV_8UC1, computed on frame `source_id`) as seen in the newest frame. Empty when the
  // source frame is older than the history or was never added.
  [[nodiscard]] cv::Mat propagate(const cv::Mat& labels, std::uint64_t source_id) const;

  // `mask` (CV_8UC1, computed on frame `source_id`) as seen in the newest frame, each 8-connected
  // object moved whole, frame by frame, by the flow most of its pixels share. Pixel-wise remapping
  // smears an object along the flow's motion boundaries, where the coarse flow drags the background
  // along with a walking person; moved whole, an object keeps its shape and size (walker, masks
  // carried 7 frames: IoU 0.54 against 0.50). Empty as for propagate().
  [[nodiscard]] cv::Mat moveObjects(const cv::Mat& mask, std::uint64_t source_id) const;

  [[nodiscard]] std::uint64_t newestFrame() const { return newest_id_; }

 private:
  struct Step {
    std::uint64_t from_id;  // the previous frame
    cv::Mat map_x;          // for each pixel of the next frame: where it was in from_id
    cv::Mat map_y;          // (both at the flow's resolution)
  };

  // Nearest-neighbour resizing between an image's size and the flow's.
  [[nodiscard]] cv::Mat toFlowResolution(const cv::Mat& image) const;
  [[nodiscard]] static cv::Mat toSizeOf(const cv::Mat& small, const cv::Mat& image);

  // The steps from `source_id` to the newest frame: their first, or steps_.end() when
  // source_id is the newest frame; nullopt when it is unknown.
  [[nodiscard]] std::optional<std::deque<Step>::const_iterator> stepsFrom(
      std::uint64_t source_id) const;

  int history_;
  double flow_scale_;
  cv::Ptr<cv::DISOpticalFlow> flow_;
  cv::Mat previous_gray_;
  std::uint64_t newest_id_ = 0;
  bool has_frame_ = false;
  std::deque<Step> steps_;
};

}  // namespace segslam::segmentation
