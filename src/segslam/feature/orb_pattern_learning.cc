#include "segslam/feature/orb_pattern_learning.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <opencv2/core/hal/hal.hpp>
#include <stdexcept>
#include <string>

namespace segslam::feature {
namespace {

// The outcome of one test on every patch, one bit per patch.
struct TestOutcomes {
  std::vector<std::uint64_t> bits;
  int ones = 0;
};

TestOutcomes outcomes(const PatchSamples& samples, int first, int second) {
  cv::Mat less;
  cv::compare(samples.intensities(first), samples.intensities(second), less, cv::CMP_LT);
  const auto* flags = less.ptr<std::uint8_t>();
  TestOutcomes result;
  result.bits.assign((samples.patchCount() + 63) / 64, 0);
  for (int patch = 0; patch < samples.patchCount(); ++patch) {
    if (flags[patch] != 0) {
      result.bits[patch / 64] |= std::uint64_t{1} << (patch % 64);
      ++result.ones;
    }
  }
  return result;
}

// Pearson correlation of two binary variables from their joint counts. The number of patches
// where both tests are 1 comes from the Hamming distance of the two bit sets (OpenCV's, which
// uses the CPU's popcount): |a & b| = (|a| + |b| - |a ^ b|) / 2.
double correlation(const TestOutcomes& a, const TestOutcomes& b, int patches) {
  const int differing = cv::hal::normHamming(
      reinterpret_cast<const uchar*>(a.bits.data()), reinterpret_cast<const uchar*>(b.bits.data()),
      static_cast<int>(a.bits.size() * sizeof(std::uint64_t)));
  const double n = patches;
  const double both = (a.ones + b.ones - differing) / 2.0;
  const double p_a = a.ones / n;
  const double p_b = b.ones / n;
  const double variance = p_a * (1.0 - p_a) * p_b * (1.0 - p_b);
  if (variance <= 0.0) return 0.0;
  return (both / n - p_a * p_b) / std::sqrt(variance);
}

bool isConstant(const TestOutcomes& outcome, int patches) {
  return outcome.ones == 0 || outcome.ones == patches;
}

bool farEnoughApart(PatternPoint a, PatternPoint b, int min_separation) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)) >= min_separation;
}

// Test outcomes by rank, computed when first needed: the greedy search makes several passes
// over the same leading part of the ranking.
class OutcomeCache {
 public:
  OutcomeCache(const PatchSamples& samples, const std::vector<CandidateTest>& ranked)
      : samples_(samples), ranked_(ranked), outcomes_(ranked.size()) {}

  const TestOutcomes& at(std::size_t rank) {
    TestOutcomes& cached = outcomes_[rank];
    if (cached.bits.empty()) cached = outcomes(samples_, ranked_[rank].first, ranked_[rank].second);
    return cached;
  }

 private:
  const PatchSamples& samples_;
  const std::vector<CandidateTest>& ranked_;
  std::vector<TestOutcomes> outcomes_;
};

// One greedy pass at a fixed correlation threshold: the first tests in rank order that correlate
// with no test picked before them by more than the threshold.
std::vector<int> greedyPass(OutcomeCache& cache, std::size_t candidates, int patches, int wanted,
                            double max_correlation) {
  std::vector<int> picked;
  for (std::size_t rank = 0; rank < candidates && static_cast<int>(picked.size()) < wanted;
       ++rank) {
    const TestOutcomes& candidate = cache.at(rank);
    if (isConstant(candidate, patches)) continue;
    // Newest picks first: a candidate tends to resemble the tests just before it in the ranking.
    const bool independent = std::all_of(picked.rbegin(), picked.rend(), [&](int other) {
      return std::abs(correlation(candidate, cache.at(other), patches)) <= max_correlation;
    });
    if (independent) picked.push_back(static_cast<int>(rank));
  }
  return picked;
}

}  // namespace

std::vector<PatternPoint> patternCandidatePoints() {
  std::vector<PatternPoint> points;
  for (int y = -kPatternRadius; y <= kPatternRadius; ++y) {
    for (int x = -kPatternRadius; x <= kPatternRadius; ++x) {
      if (x * x + y * y <= kPatternRadius * kPatternRadius) {
        points.push_back({static_cast<std::int8_t>(x), static_cast<std::int8_t>(y)});
      }
    }
  }
  return points;
}

PatchSamples::PatchSamples(std::vector<PatternPoint> points)
    : points_(std::move(points)), rows_(points_.size()) {}

void PatchSamples::addPatch(const cv::Mat& smoothed, cv::Point center, float angle_degrees) {
  const double radians = angle_degrees * (std::numbers::pi / 180.0);
  const auto cos_angle = static_cast<float>(std::cos(radians));
  const auto sin_angle = static_cast<float>(std::sin(radians));
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const cv::Point offset = steerPatternPoint(points_[i], cos_angle, sin_angle);
    rows_[i].push_back(smoothed.at<std::uint8_t>(center + offset));
  }
  ++patch_count_;
}

cv::Mat PatchSamples::intensities(int point) const { return cv::Mat(rows_[point], false); }

int PatchSamples::indexOf(PatternPoint point) const {
  const auto found = std::find_if(points_.begin(), points_.end(), [point](PatternPoint p) {
    return p.x == point.x && p.y == point.y;
  });
  return found == points_.end() ? -1 : static_cast<int>(found - points_.begin());
}

std::vector<CandidateTest> rankCandidateTests(const PatchSamples& samples,
                                              const PatternLearningOptions& options) {
  const auto& points = samples.points();
  const int patches = samples.patchCount();
  std::vector<CandidateTest> candidates;
  cv::Mat less;
  for (std::size_t first = 0; first < points.size(); ++first) {
    for (std::size_t second = first + 1; second < points.size(); ++second) {
      if (!farEnoughApart(points[first], points[second], options.min_point_separation)) continue;
      cv::compare(samples.intensities(static_cast<int>(first)),
                  samples.intensities(static_cast<int>(second)), less, cv::CMP_LT);
      const double mean = patches > 0 ? cv::countNonZero(less) / static_cast<double>(patches) : 0;
      candidates.push_back({static_cast<int>(first), static_cast<int>(second), mean});
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const CandidateTest& a, const CandidateTest& b) {
                     return std::abs(a.mean - 0.5) < std::abs(b.mean - 0.5);
                   });
  return candidates;
}

LearnedTests learnBinaryTests(const PatchSamples& samples, const PatternLearningOptions& options) {
  if (samples.patchCount() == 0) {
    throw std::invalid_argument("learnBinaryTests: no training patches");
  }
  const std::vector<CandidateTest> ranked = rankCandidateTests(samples, options);
  if (static_cast<int>(ranked.size()) < options.num_tests) {
    throw std::invalid_argument("learnBinaryTests: only " + std::to_string(ranked.size()) +
                                " candidate tests for " + std::to_string(options.num_tests));
  }
  LearnedTests learned;
  learned.candidate_tests = static_cast<int>(ranked.size());
  learned.max_correlation = options.max_correlation;
  OutcomeCache cache(samples, ranked);
  std::vector<int> picked;
  while (true) {
    picked = greedyPass(cache, ranked.size(), samples.patchCount(), options.num_tests,
                        learned.max_correlation);
    if (static_cast<int>(picked.size()) == options.num_tests || learned.max_correlation >= 1.0) {
      break;
    }
    learned.max_correlation += options.correlation_step;
  }
  const auto& points = samples.points();
  for (const int rank : picked) {
    learned.tests.push_back({points[ranked[rank].first], points[ranked[rank].second]});
    learned.means.push_back(ranked[rank].mean);
  }
  return learned;
}

PatternStatistics patternStatistics(const PatchSamples& samples,
                                    const std::vector<BinaryTest>& tests) {
  const int patches = samples.patchCount();
  if (tests.empty() || patches == 0) return {};
  std::vector<TestOutcomes> all;
  PatternStatistics statistics;
  for (const BinaryTest& test : tests) {
    const int first = samples.indexOf(test.first);
    const int second = samples.indexOf(test.second);
    if (first < 0 || second < 0) {
      throw std::invalid_argument("patternStatistics: a test point is not a sampled point");
    }
    all.push_back(outcomes(samples, first, second));
    statistics.mean_abs_bias += std::abs(all.back().ones / static_cast<double>(patches) - 0.5);
  }
  statistics.mean_abs_bias /= static_cast<double>(tests.size());
  int pairs = 0;
  for (std::size_t a = 0; a < all.size(); ++a) {
    for (std::size_t b = a + 1; b < all.size(); ++b) {
      const double r = std::abs(correlation(all[a], all[b], patches));
      statistics.mean_abs_correlation += r;
      statistics.max_abs_correlation = std::max(statistics.max_abs_correlation, r);
      ++pairs;
    }
  }
  if (pairs > 0) statistics.mean_abs_correlation /= pairs;
  return statistics;
}

}  // namespace segslam::feature
