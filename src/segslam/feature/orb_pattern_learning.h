#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "segslam/feature/orb_pattern.h"

namespace segslam::feature {

// Learning the descriptor's binary tests as Rublee et al. (2011, section 4.3) describe: from
// patches around real keypoints, greedily pick tests whose outcome is as uncertain as possible
// (mean near 0.5: high variance, so each bit says something) and that are uncorrelated with the
// tests already picked (so the bits say different things). Used by tools/learn_orb_pattern.cc.

// Every pixel offset within kPatternRadius of the centre: where test points may lie.
std::vector<PatternPoint> patternCandidatePoints();

// Training data: for each patch (a keypoint in a smoothed level image), the intensity at every
// candidate point after steering by the keypoint's angle, exactly as the descriptor samples it.
// Stored point-major (one contiguous row of patches per point), so that evaluating a test on all
// patches is a single vectorised comparison of two rows.
class PatchSamples {
 public:
  explicit PatchSamples(std::vector<PatternPoint> points);

  // `center` at least kPatternRadius from the border of `smoothed` (CV_8UC1).
  void addPatch(const cv::Mat& smoothed, cv::Point center, float angle_degrees);

  [[nodiscard]] const std::vector<PatternPoint>& points() const { return points_; }
  [[nodiscard]] int patchCount() const { return patch_count_; }
  // patchCount x 1 CV_8U: the intensity of point `point` in every patch. A view, valid until the
  // next addPatch.
  [[nodiscard]] cv::Mat intensities(int point) const;
  // Index of `point` in points(), or -1.
  [[nodiscard]] int indexOf(PatternPoint point) const;

 private:
  std::vector<PatternPoint> points_;
  std::vector<std::vector<std::uint8_t>> rows_;
  int patch_count_ = 0;
};

struct PatternLearningOptions {
  int num_tests = kDescriptorBits;
  // The two points of a test are at least this far apart in x or y. Rublee et al. compare
  // non-overlapping 5 x 5 sub-windows; with the Gaussian smoothing, closer points would give
  // tests that mostly measure noise while still scoring a mean near 0.5.
  int min_point_separation = 5;
  // Greedy threshold on |correlation| with every test already picked; raised by
  // correlation_step until num_tests are found, as in the paper.
  double max_correlation = 0.2;
  double correlation_step = 0.02;
};

// A test's first and second point as indices into PatchSamples::points().
struct CandidateTest {
  int first = 0;
  int second = 0;
  double mean = 0.0;  // share of patches where intensity(first) < intensity(second)
};

struct LearnedTests {
  std::vector<BinaryTest> tests;
  std::vector<double> means;     // per chosen test, on the training patches
  double max_correlation = 0.0;  // the threshold the greedy search finally used
  int candidate_tests = 0;       // how many tests were considered
};

// All candidate tests with their means, most uncertain (|mean - 0.5| smallest) first; ties keep
// enumeration order so that the result is deterministic.
std::vector<CandidateTest> rankCandidateTests(const PatchSamples& samples,
                                              const PatternLearningOptions& options);

// Greedy selection over the ranked tests. Throws std::invalid_argument when there are fewer
// candidate tests than options.num_tests, or no patches.
LearnedTests learnBinaryTests(const PatchSamples& samples, const PatternLearningOptions& options);

// How good a set of tests is on some patches: the average |mean - 0.5| (0 is best) and the
// average and largest |correlation| between two of the tests (0 is best).
struct PatternStatistics {
  double mean_abs_bias = 0.0;
  double mean_abs_correlation = 0.0;
  double max_abs_correlation = 0.0;
};

// Throws std::invalid_argument when a test point is not one of samples.points().
PatternStatistics patternStatistics(const PatchSamples& samples,
                                    const std::vector<BinaryTest>& tests);

}  // namespace segslam::feature
