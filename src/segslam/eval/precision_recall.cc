#include "segslam/eval/precision_recall.h"

#include <algorithm>
#include <limits>

namespace segslam::eval {

PrCurve precisionRecall(std::span<const ScoredPair> pairs) {
  std::vector<ScoredPair> sorted(pairs.begin(), pairs.end());
  std::sort(sorted.begin(), sorted.end(),
            [](const ScoredPair& a, const ScoredPair& b) { return a.score > b.score; });
  PrCurve curve;
  for (const auto& pair : sorted) ++(pair.positive ? curve.positives : curve.negatives);
  if (curve.positives == 0) {
    curve.average_precision = std::numeric_limits<double>::quiet_NaN();
    return curve;
  }
  const auto positives = static_cast<double>(curve.positives);
  std::size_t true_positives = 0;
  double previous_recall = 0.0;
  for (std::size_t k = 0; k < sorted.size();) {
    const double threshold = sorted[k].score;
    for (; k < sorted.size() && sorted[k].score == threshold; ++k) {
      if (sorted[k].positive) ++true_positives;
    }
    const double precision = static_cast<double>(true_positives) / static_cast<double>(k);
    const double recall = static_cast<double>(true_positives) / positives;
    curve.average_precision += (recall - previous_recall) * precision;
    previous_recall = recall;
    curve.points.push_back({threshold, precision, recall});
  }
  return curve;
}

}  // namespace segslam::eval
