#include "segslam/eval/rpe_pairs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <numbers>
#include <stdexcept>

#include "segslam/eval/closest_index.h"

namespace segslam::eval {

namespace {

struct UnitName {
  DeltaUnit unit;
  std::string_view name;
};

constexpr std::array<UnitName, 5> kUnitNames{{
    {DeltaUnit::kSeconds, "s"},
    {DeltaUnit::kFrames, "f"},
    {DeltaUnit::kMeters, "m"},
    {DeltaUnit::kDegrees, "deg"},
    {DeltaUnit::kRadians, "rad"},
}};

// The motion between consecutive poses as the tool writes it: inv(T[k+1]) * T[k].
template <typename Measure>
std::vector<double> accumulateMotion(const core::Trajectory& trajectory, Measure measure) {
  std::vector<double> accumulated{0.0};
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < trajectory.size(); ++k) {
    sum += measure(trajectory[k + 1].T_wc.inverse() * trajectory[k].T_wc);
    accumulated.push_back(sum);
  }
  return accumulated;
}

}  // namespace

std::string_view deltaUnitName(DeltaUnit unit) {
  for (const auto& entry : kUnitNames) {
    if (entry.unit == unit) return entry.name;
  }
  throw std::invalid_argument("unknown delta unit");
}

std::vector<std::string> deltaUnitNames() {
  std::vector<std::string> names;
  for (const auto& entry : kUnitNames) names.emplace_back(entry.name);
  return names;
}

std::optional<DeltaUnit> parseDeltaUnit(std::string_view name) {
  for (const auto& entry : kUnitNames) {
    if (entry.name == name) return entry.unit;
  }
  return std::nullopt;
}

std::vector<double> deltaIndex(const core::Trajectory& estimate, DeltaUnit unit) {
  switch (unit) {
    case DeltaUnit::kSeconds:
      return estimate.timestamps();
    case DeltaUnit::kFrames: {
      std::vector<double> frames(estimate.size());
      for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = static_cast<double>(i);
      return frames;
    }
    case DeltaUnit::kMeters:
      return accumulateMotion(estimate,
                              [](const geometry::Pose& m) { return m.translation().norm(); });
    case DeltaUnit::kRadians:
      return accumulateMotion(estimate, geometry::rotationAngle);
    case DeltaUnit::kDegrees:
      return accumulateMotion(estimate, [](const geometry::Pose& m) {
        return geometry::rotationAngle(m) * 180.0 / std::numbers::pi;
      });
  }
  throw std::invalid_argument("unknown delta unit");
}

std::vector<PosePair> fixedDeltaPairs(std::span<const double> index, double delta) {
  std::vector<PosePair> pairs;
  for (std::size_t i = 0; i < index.size(); ++i) {
    const std::size_t j = findClosestIndex(index, index[i] + delta);
    // The tool drops these, presumably to discard deltas cut short by the end of the sequence;
    // it also drops honest pairs ending at the last pose, and so do we, to match its figures.
    if (j != index.size() - 1) pairs.emplace_back(i, j);
  }
  return pairs;
}

std::vector<PosePair> allOrRandomPairs(std::size_t pose_count, std::size_t max_pairs,
                                       std::mt19937_64& rng) {
  std::vector<PosePair> pairs;
  const bool all =
      max_pairs == 0 || static_cast<double>(pose_count) < std::sqrt(static_cast<double>(max_pairs));
  if (all) {
    for (std::size_t i = 0; i < pose_count; ++i) {
      for (std::size_t j = 0; j < pose_count; ++j) pairs.emplace_back(i, j);
    }
    return pairs;
  }
  std::uniform_int_distribution<std::size_t> pick(0, pose_count - 1);
  for (std::size_t k = 0; k < max_pairs; ++k) {
    const std::size_t i = pick(rng);
    pairs.emplace_back(i, pick(rng));
  }
  return pairs;
}

std::vector<PosePair> limitPairs(std::vector<PosePair> pairs, std::size_t max_pairs,
                                 std::mt19937_64& rng) {
  if (max_pairs == 0 || pairs.size() <= max_pairs) return pairs;
  std::vector<PosePair> sampled;
  sampled.reserve(max_pairs);
  std::sample(pairs.begin(), pairs.end(), std::back_inserter(sampled), max_pairs, rng);
  return sampled;
}

}  // namespace segslam::eval
