#include "segslam/eval/alignment.h"

#include <Eigen/SVD>
#include <array>
#include <stdexcept>

namespace segslam::eval {

namespace {

struct MethodName {
  AlignmentMethod method;
  std::string_view name;
};

constexpr std::array<MethodName, 3> kMethodNames{{
    {AlignmentMethod::kSe3, "se3"},
    {AlignmentMethod::kSim3, "sim3"},
    {AlignmentMethod::kNone, "none"},
}};

}  // namespace

std::string_view alignmentMethodName(AlignmentMethod method) {
  for (const auto& entry : kMethodNames) {
    if (entry.method == method) return entry.name;
  }
  throw std::invalid_argument("unknown alignment method");
}

std::vector<std::string> alignmentMethodNames() {
  std::vector<std::string> names;
  for (const auto& entry : kMethodNames) names.emplace_back(entry.name);
  return names;
}

std::optional<AlignmentMethod> parseAlignmentMethod(std::string_view name) {
  for (const auto& entry : kMethodNames) {
    if (entry.name == name) return entry.method;
  }
  return std::nullopt;
}

Eigen::Vector3d Alignment::apply(const Eigen::Vector3d& point) const {
  return scale * (rotation * point) + translation;
}

geometry::Pose Alignment::apply(const geometry::Pose& pose) const {
  geometry::Pose aligned = geometry::Pose::Identity();
  aligned.linear() = rotation * pose.linear();
  aligned.translation() = apply(Eigen::Vector3d(pose.translation()));
  return aligned;
}

Alignment Alignment::inverse() const {
  Alignment inverted;
  inverted.rotation = rotation.transpose();
  inverted.scale = 1.0 / scale;
  inverted.translation = -inverted.scale * (inverted.rotation * translation);
  return inverted;
}

Eigen::Matrix4d Alignment::matrix() const {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = scale * rotation;
  m.topRightCorner<3, 1>() = translation;
  return m;
}

Alignment alignPoints(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                      AlignmentMethod method) {
  if (source.cols() != target.cols() || source.cols() == 0) {
    throw std::invalid_argument("alignPoints needs two non-empty point sets of the same size");
  }
  Alignment alignment;
  if (method == AlignmentMethod::kNone) return alignment;

  const Eigen::Vector3d source_mean = source.rowwise().mean();
  const Eigen::Vector3d target_mean = target.rowwise().mean();
  const Eigen::Matrix3Xd source_centred = source.colwise() - source_mean;
  const Eigen::Matrix3Xd target_centred = target.colwise() - target_mean;
  const Eigen::Matrix3d W = source_centred * target_centred.transpose();

  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(W.transpose(),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  // A reflection would fit better than any rotation only for degenerate or mirrored data.
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) S(2, 2) = -1.0;
  alignment.rotation = svd.matrixU() * S * svd.matrixV().transpose();

  if (method == AlignmentMethod::kSim3) {
    const double source_spread = source_centred.squaredNorm();
    // All source points coincide: no scale can be observed, so keep it neutral.
    if (source_spread > 0.0) {
      alignment.scale = (svd.singularValues().asDiagonal() * S).trace() / source_spread;
    }
  }
  alignment.translation = target_mean - alignment.scale * alignment.rotation * source_mean;
  return alignment;
}

}  // namespace segslam::eval
