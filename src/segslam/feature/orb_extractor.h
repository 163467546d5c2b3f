#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segslam/feature/orb_descriptor.h"
#include "segslam/feature/scale_levels.h"
#include "segslam/feature/static_mask.h"

namespace segslam::feature {

struct OrbExtractorOptions {
  // Keypoints per frame over all levels (fewer only if the static area has fewer corners).
  int num_features = 1000;
  double scale_factor = 1.2;
  int num_levels = 8;
  // FAST thresholds: the first is tried in every grid cell, the second where it finds nothing.
  int initial_fast_threshold = 20;
  int min_fast_threshold = 7;
  // Side of the grid cells FAST runs in, in level pixels.
  int cell_size = 30;
  // Keypoint centres keep this distance (level-0 pixels, Euclidean) from every dynamic pixel.
  // The radius is the same at every level when measured in level-0 pixels, i.e. it shrinks to
  // radius / scale^level in the pixels of level `level`.
  int mask_dilation_px = 10;
  // Works on the pyramid levels in parallel (TBB). The output is identical either way.
  bool parallel_levels = false;
};

// ORB features (Rublee et al. 2011) the way ORB-SLAM uses them: FAST corners per grid cell on a
// scale pyramid, spread evenly by a quadtree per level, oriented by intensity centroid, described
// by steered BRIEF with our learned test pattern. A dynamic mask keeps keypoints off moving objects
// while the static area still receives the whole feature budget.
//
// Not thread-safe: an extractor keeps its pyramid buffers between frames; use one per thread.
class OrbExtractor {
 public:
  // Throws std::invalid_argument on nonsensical options.
  explicit OrbExtractor(const OrbExtractorOptions& options = {});
  // Copies would share the pyramid buffers (cv::Mat copies share data) and race when used from
  // two threads; moving is fine.
  OrbExtractor(const OrbExtractor&) = delete;
  OrbExtractor& operator=(const OrbExtractor&) = delete;
  OrbExtractor(OrbExtractor&&) = default;
  OrbExtractor& operator=(OrbExtractor&&) = default;

  // gray: CV_8UC1. dynamic_mask: empty (all static) or CV_8UC1 of gray's size, non-zero = dynamic.
  // keypoints: level-0 coordinates, octave = level, size = patch diameter x scale, angle in
  // degrees [0, 360), response = FAST score; ordered by level. descriptors: N x 32 CV_8U, row i
  // for keypoint i. Same input, same output. Throws std::invalid_argument on invalid input.
  void extract(const cv::Mat& gray, const cv::Mat& dynamic_mask,
               std::vector<cv::KeyPoint>& keypoints, cv::Mat& descriptors);
  // The same keypoints without descriptors.
  void detect(const cv::Mat& gray, const cv::Mat& dynamic_mask,
              std::vector<cv::KeyPoint>& keypoints);

  [[nodiscard]] const OrbExtractorOptions& options() const { return options_; }
  [[nodiscard]] int numLevels() const { return scale_levels_.numLevels(); }
  [[nodiscard]] double scaleFactor() const { return scale_levels_.factor(); }
  [[nodiscard]] const ScaleLevels& scaleLevels() const { return scale_levels_; }
  // scale^level, its inverse, and the per-level variance scale^(2 level) and its inverse.
  [[nodiscard]] const std::vector<double>& scaleFactors() const { return scale_levels_.scales(); }
  [[nodiscard]] const std::vector<double>& inverseScaleFactors() const {
    return scale_levels_.inverseScales();
  }
  [[nodiscard]] const std::vector<double>& levelSigma2() const { return scale_levels_.sigma2(); }
  [[nodiscard]] const std::vector<double>& inverseLevelSigma2() const {
    return scale_levels_.inverseSigma2();
  }
  // The pyramid of the last image processed (level 0 is that image).
  [[nodiscard]] const std::vector<cv::Mat>& pyramid() const { return pyramid_; }

 private:
  void run(const cv::Mat& gray, const cv::Mat& dynamic_mask, std::vector<cv::KeyPoint>& keypoints,
           cv::Mat* descriptors);
  template <typename LevelWork>
  void forEachLevel(const LevelWork& work) const;
  void orientAndDescribe(int level, std::vector<cv::KeyPoint>& level_keypoints,
                         cv::Mat* descriptors);

  OrbExtractorOptions options_;
  ScaleLevels scale_levels_;
  SteeredBrief brief_;
  std::vector<int> level_shares_;
  std::vector<cv::Mat> pyramid_;
  std::vector<cv::Mat> smoothed_;  // per level, so that levels can run in parallel
  StaticMask static_mask_;         // the last frame's, its buffers reused
};

}  // namespace segslam::feature
