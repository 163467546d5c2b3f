#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace segslam::eval {

struct ScoredPair {
  double score = 0.0;  // higher = more likely the same place
  bool positive = false;
};

struct PrPoint {
  double threshold = 0.0;  // pairs scoring >= threshold are called loops
  double precision = 0.0;
  double recall = 0.0;
};

struct PrCurve {
  std::vector<PrPoint> points;  // one per distinct score, from the highest threshold down
  // Average precision: sum over thresholds of (recall step) x precision, i.e. the area under
  // the step-interpolated PR curve (no trapezoids, which overrate sparse curves). NaN without
  // positives.
  double average_precision = 0.0;
  std::size_t positives = 0;
  std::size_t negatives = 0;
};

// The precision-recall curve of a scorer swept over every threshold. Tied scores are one
// threshold: they are accepted or rejected together.
PrCurve precisionRecall(std::span<const ScoredPair> pairs);

}  // namespace segslam::eval
