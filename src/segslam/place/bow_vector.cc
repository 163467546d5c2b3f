#include "segslam/place/bow_vector.h"

#include <cmath>

namespace segslam::place {

namespace {

double l1Norm(const BowVector& vector) {
  double norm = 0.0;
  for (const auto& [word, weight] : vector) norm += std::abs(weight);
  return norm;
}

}  // namespace

void normaliseL1(BowVector& vector) {
  const double norm = l1Norm(vector);
  if (norm <= 0.0) return;
  for (auto& [word, weight] : vector) weight /= norm;
}

double l1Score(const BowVector& a, const BowVector& b) {
  const double norm_a = l1Norm(a);
  const double norm_b = l1Norm(b);
  if (norm_a <= 0.0 || norm_b <= 0.0) return 0.0;
  double distance = 0.0;
  auto it_a = a.begin();
  auto it_b = b.begin();
  while (it_a != a.end() || it_b != b.end()) {
    if (it_b == b.end() || (it_a != a.end() && it_a->first < it_b->first)) {
      distance += std::abs(it_a++->second) / norm_a;
    } else if (it_a == a.end() || it_b->first < it_a->first) {
      distance += std::abs(it_b++->second) / norm_b;
    } else {
      distance += std::abs(it_a++->second / norm_a - it_b++->second / norm_b);
    }
  }
  const double score = 1.0 - 0.5 * distance;
  return score < 0.0 ? 0.0 : (score > 1.0 ? 1.0 : score);
}

}  // namespace segslam::place
