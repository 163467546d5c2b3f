#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace segslam::segmentation {

struct DepthRefinementOptions {
  // The mask's interior (eroded by this much) seeds the object; its border is left to depth.
  int core_erosion_px = 4;
  // Seeds are taken on a grid of this step inside the interior (a fill covers its neighbours).
  int seed_step_px = 4;
  // Neighbouring pixels belong to the same object when their depths differ by less than this.
  double max_depth_step_m = 0.03;
  // A region is one of the known objects when its median depth is within this share of theirs,
  // or within this many metres: a person leaning over the camera comes from 0.36 to 0.27 m within
  // six frames, and against a fifth of the depth he had in the network's frame he was dropped as
  // background, the whole person unmasked at once. (Only objects nearer than 0.75 m are concerned:
  // in the shared Bonn crowd frames, whose people stay 0.84 m away or more, nothing changes.)
  double object_depth_tolerance = 0.2;
  double min_object_depth_tolerance_m = 0.15;
  // Smaller parts of a mask get no depth of their own (noise, thin limbs at the border).
  int min_object_area_px = 200;
  // A region at a known object's depth that lies mostly outside the mask keeps its part inside the
  // mask: a person at a desk at his own depth is one region with it. Off, such a region is
  // dropped, which tells an object that has merged into a larger surface (a lost object, gone).
  bool keep_masked_part_of_joined_objects = true;
  // The refinement runs at 1/downscale of the image's resolution (the pixel options above stay in
  // the image's pixels) and its result is scaled back: a carried mask comes from the optical
  // flow's half resolution, and SLAM dilates the mask by more than the lost detail anyway.
  int downscale = 1;
};

// Median depth of each connected part of the mask (parts of at least min_object_area_px pixels
// with depth): where the objects were when the mask was made.
std::vector<float> objectDepths(const cv::Mat& mask, const cv::Mat& depth,
                                const DepthRefinementOptions& options = {});

// Snaps an approximate object mask (a network output at its coarse resolution, or one carried
// over from an older frame) to the object's outline in the depth image: the object is the set of
// pixels depth-connected to the mask's interior, searched within `band_px` around the mask.
// A mask that lags behind a moving person thus follows the person as far as the band reaches,
// instead of being grown blindly in every direction. Given object_depths (see objectDepths), a
// region at another depth than the objects' is dropped: the background a person has just
// uncovered. A region that lies mostly inside the mask is kept whole; one mostly outside it is
// dropped, or, at an object's depth, kept where the mask covers it (see
// keep_masked_part_of_joined_objects). Pixels of the mask without depth are kept, and so are
// parts too thin to hold an interior. mask: CV_8UC1 (non-zero = object); depth:
// CV_32FC1 metres (0 = none). Empty depth: unchanged.
cv::Mat refineMaskByDepth(const cv::Mat& mask, const cv::Mat& depth, int band_px,
                          const std::vector<float>& object_depths = {},
                          const DepthRefinementOptions& options = {});

}  // namespace segslam::segmentation
