#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>

#include "segslam/optim/bundle_adjuster.h"

namespace segslam::optim {

// Assembles a BundleAdjustmentProblem while the caller walks its map in whatever order suits it
// (keyframes, then their points, then the points' other observers): every keyframe and point
// id gets exactly one slot, however often it is added.
class BaProblemBuilder {
 public:
  explicit BaProblemBuilder(const StereoIntrinsics& intrinsics);

  // Index of the keyframe's slot. A keyframe added again keeps its first pose and fixed flag.
  std::size_t addKeyFrame(std::uint64_t id, const geometry::Pose& T_cw, bool fixed);
  // Index of the point's slot. A point added again keeps its first position.
  std::size_t addPoint(std::uint64_t id, const Eigen::Vector3d& position);
  void addObservation(std::size_t keyframe, std::size_t point, const RgbdObservation& observation);

  [[nodiscard]] std::optional<std::size_t> keyFrameIndex(std::uint64_t id) const;
  [[nodiscard]] std::optional<std::size_t> pointIndex(std::uint64_t id) const;

  [[nodiscard]] const BundleAdjustmentProblem& problem() const { return problem_; }
  // Hands the assembled problem over; the builder is empty afterwards.
  [[nodiscard]] BundleAdjustmentProblem take();

 private:
  BundleAdjustmentProblem problem_;
  std::unordered_map<std::uint64_t, std::size_t> keyframe_index_;
  std::unordered_map<std::uint64_t, std::size_t> point_index_;
};

}  // namespace segslam::optim
