#include "segslam/optim/ba_problem_builder.h"

#include <utility>

namespace segslam::optim {
namespace {

std::optional<std::size_t> lookUp(const std::unordered_map<std::uint64_t, std::size_t>& index,
                                  std::uint64_t id) {
  const auto it = index.find(id);
  if (it == index.end()) return std::nullopt;
  return it->second;
}

}  // namespace

BaProblemBuilder::BaProblemBuilder(const StereoIntrinsics& intrinsics) {
  problem_.intrinsics = intrinsics;
}

std::size_t BaProblemBuilder::addKeyFrame(std::uint64_t id, const geometry::Pose& T_cw,
                                          bool fixed) {
  const auto [it, inserted] = keyframe_index_.try_emplace(id, problem_.keyframes.size());
  if (inserted) problem_.keyframes.push_back({id, T_cw, fixed});
  return it->second;
}

std::size_t BaProblemBuilder::addPoint(std::uint64_t id, const Eigen::Vector3d& position) {
  const auto [it, inserted] = point_index_.try_emplace(id, problem_.points.size());
  if (inserted) problem_.points.push_back({id, position});
  return it->second;
}

void BaProblemBuilder::addObservation(std::size_t keyframe, std::size_t point,
                                      const RgbdObservation& observation) {
  problem_.observations.push_back({keyframe, point, observation});
}

std::optional<std::size_t> BaProblemBuilder::keyFrameIndex(std::uint64_t id) const {
  return lookUp(keyframe_index_, id);
}

std::optional<std::size_t> BaProblemBuilder::pointIndex(std::uint64_t id) const {
  return lookUp(point_index_, id);
}

BundleAdjustmentProblem BaProblemBuilder::take() {
  BundleAdjustmentProblem taken = std::move(problem_);
  problem_ = BundleAdjustmentProblem{taken.intrinsics, {}, {}, {}};
  keyframe_index_.clear();
  point_index_.clear();
  return taken;
}

}  // namespace segslam::optim
