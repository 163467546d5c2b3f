#pragma once

#include <opencv2/core.hpp>

#include "segslam/core/camera.h"
#include "segslam/dense/labelled_cloud.h"

namespace segslam::dense {

// The images of one keyframe that the dense map is made of.
struct KeyFrameImages {
  cv::Mat bgr;           // CV_8UC3
  cv::Mat depth;         // CV_32FC1 metres, 0 = no measurement
  cv::Mat dynamic_mask;  // CV_8UC1, non-zero = dynamic, not dilated; empty = all static
  cv::Mat labels;        // CV_8UC1 core::SemanticClass ids; empty = unknown
  cv::Mat instances;     // CV_16UC1 instance ids, 0 = none; empty = none
};

struct KeyFrameCloudOptions {
  double voxel_size = 0.01;  // metres, > 0
  // Depth measurements beyond this range are too noisy for the map (metres).
  double max_depth = 5.0;
  // The dynamic mask is dilated by this many pixels before the static cloud is taken, as for
  // keypoints: segmentation is least reliable on an object's border.
  int mask_dilation_px = 10;
  // Pixels whose depth differs from a 4-neighbour's by more than this share of their own depth
  // lie on a depth discontinuity, where sensors return points between the two surfaces.
  double depth_edge_ratio = 0.05;
  // Pixels are taken with a stride such that up to this depth neighbouring samples still lie at
  // most one voxel apart: every voxel a surface crosses keeps points, while a 1 cm map of a
  // 525 px focal length camera back-projects a quarter of the pixels.
  double full_sampling_depth = 2.0;
};

// Both layers of one keyframe, in its camera frame, voxel-downsampled so that a keyframe's
// memory is bounded by what its view covers.
struct KeyFrameCloud {
  LabelledCloud static_points;   // pixels outside the dilated dynamic mask
  LabelledCloud dynamic_points;  // pixels inside the (undilated) dynamic mask
  // Static surface that culled keyframes saw and this one did not (foldInto): part of the map,
  // but not this keyframe's view, so no vote for the objects it sees.
  LabelledCloud folded_points;
};

// Back-projects every pixel with valid depth, z = depth, (x, y) = z * undistorted normalised
// pixel coordinates (for a camera without distortion: x = (u - cx) z / fx, y = (v - cy) z / fy).
class KeyFrameCloudMaker {
 public:
  KeyFrameCloudMaker(const core::Camera& camera, KeyFrameCloudOptions options);

  // Throws std::invalid_argument when an image has the wrong type or size.
  [[nodiscard]] KeyFrameCloud make(const KeyFrameImages& images) const;
  // make() in two steps, to time them: the sampled pixels' points, then one point per voxel.
  [[nodiscard]] KeyFrameCloud backProject(const KeyFrameImages& images) const;
  [[nodiscard]] KeyFrameCloud downsample(const KeyFrameCloud& cloud) const;

  [[nodiscard]] const KeyFrameCloudOptions& options() const { return options_; }
  // Every stride-th pixel of every stride-th row is back-projected.
  [[nodiscard]] int samplingStride() const { return stride_; }

 private:
  [[nodiscard]] bool onDepthEdge(const cv::Mat& depth, int row, int col) const;

  core::Camera camera_;
  KeyFrameCloudOptions options_;
  int stride_ = 1;
  cv::Mat normalised_;  // CV_32FC2: undistorted (x/z, y/z) of every pixel
};

}  // namespace segslam::dense
